// test_caps_iso.cpp - the world-space isotropic sampler (Benyoub 2024) against the tangent-space
// caps sampler: per sample for n = z, in pdf for a rotated normal, and in normalization.
#include <doctest/doctest.h>

#include "ggx_quadrature.hpp"
#include "ref_test_helpers.hpp"

using namespace reftest;

namespace {

std::vector<Vec3> normals()
{
    return {normalize({0.3, -0.5, 0.8}), normalize({-0.9, 0.2, 0.1}), normalize({0.1, 0.6, -0.7}),
            normalize({1e-3, 0.0, -1.0})};  // near the singular n = -z
}

// The blog's appendix pdf, written out independently: alpha^2 / (4 pi N^2 sigma).
double blog_pdf(const Vec3& o, const Vec3& i, double alpha, const Vec3& n)
{
    const double a2 = alpha * alpha;
    const Vec3 m = normalize(o + i);
    const double zm = dot(m, n), zi = dot(i, n);
    const double nrm = 1.0 / std::sqrt(zi * zi * (1.0 - a2) + a2);
    const double sigma = (zi * nrm * 0.5 + 0.5) / nrm;
    const double N = zm * zm * (a2 - 1.0) + 1.0;
    return a2 / (pi * 4.0 * N * N * sigma);
}

}  // namespace

TEST_CASE("caps-iso with n = z is the caps sampler turned by pi about n")
{
    for (double alpha : {0.05, 0.5, 1.7})
        for (double theta : {0.0, 40.0, 80.0, 120.0}) {
            const Params p = params(Method::caps, alpha, alpha, theta);
            for (double u1 : {0.05, 0.3, 0.45})
                for (double u2 : {0.1, 0.6, 0.95}) {
                    const Vec3 a = sample_normal(Method::caps_iso, p, u1, u2),
                               b = sample_normal(Method::caps, p, u1 + 0.5, u2);
                    CHECK(length(a - b) < 1e-13);
                }
        }
}

TEST_CASE("caps-iso about a rotated normal has the caps pdf of the rotated frame")
{
    for (const Vec3& n : normals()) {
        const Rotation R = rotation_to(n);
        for (double alpha : {0.02, 0.4, 1.5})
            for (double theta : {0.0, 35.0, 85.0, 130.0}) {
                const Params local = params(Method::caps, alpha, alpha, theta);
                const Params world{alpha, alpha, R.apply(local.i), n};
                for (double u1 : {0.1, 0.55, 0.9})
                    for (double u2 : {0.2, 0.5, 0.85}) {
                        const Sample s = sample(Method::caps_iso, world, u1, u2);
                        CAPTURE(n.z);
                        CAPTURE(theta);
                        CHECK(dot(s.m, n) > 0.0);
                        CHECK(close_rel(s.pdf_o, pdf_o(Method::caps_iso, world, s.o), 1e-9));
                        CHECK(close_rel(s.pdf_m, pdf_m(Method::caps_iso, world, s.m), 1e-9));
                        CHECK(close_rel(s.pdf_o, pdf_o(Method::caps, local, R.inverse(s.o)), 1e-8));
                        CHECK(close_rel(s.pdf_m, pdf_m(Method::caps, local, R.inverse(s.m)), 1e-8));
                        CHECK(close_rel(s.pdf_o, blog_pdf(s.o, world.i, alpha, n), 1e-7));
                    }
            }
    }
}

TEST_CASE("caps-iso about a rotated normal integrates to 1 and keeps the tangent-space albedo")
{
    for (const Vec3& n : normals()) {
        const Rotation R = rotation_to(n);
        for (double alpha : {0.05, 0.6})
            for (double theta : {20.0, 75.0, 140.0}) {
                const Params local = params(Method::caps, alpha, alpha, theta, 1.1);
                const Params world{alpha, alpha, R.apply(local.i), n};
                CHECK(integrate_pdf_o(Method::caps_iso, world) == doctest::Approx(1.0).epsilon(1e-9));
                CHECK(integrate_pdf_o_upper(Method::caps_iso, world) ==
                      doctest::Approx(integrate_pdf_o_upper(Method::caps, local)).epsilon(1e-9));
                if (theta < 90.0)
                    CHECK(albedo(world) == doctest::Approx(albedo(local)).epsilon(1e-9));
            }
    }
}
