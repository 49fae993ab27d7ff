// test_samplers.cpp - every sampler on a grid of alphas, views and uniforms: unit m with mz > 0,
// unit o, and the pdfs it reports equal to the pdfs recomputed from m and from (i, o) alone.
#include <doctest/doctest.h>

#include <string>

#include "ref_test_helpers.hpp"

using namespace reftest;

namespace {

std::vector<double> interior_uniforms()
{
    std::vector<double> u;
    for (int k = 0; k < 7; ++k)
        u.push_back((k + 0.5) / 7.0);
    return u;
}

void check_sample(Method method, const Params& p, double u1, double u2)
{
    CAPTURE(u1);
    CAPTURE(u2);
    const Sample s = sample(method, p, u1, u2);
    const Vec3 n = method == Method::caps_iso ? p.n : Vec3{0, 0, 1};
    CHECK(length(s.m) == doctest::Approx(1.0).epsilon(1e-14));
    CHECK(length(s.o) == doctest::Approx(1.0).epsilon(1e-14));
    CHECK(dot(s.m, n) > 0.0);
    CHECK(s.pdf_o > 0.0);
    CHECK(std::isfinite(s.pdf_o));
    CHECK(close_rel(s.pdf_m, pdf_m(method, p, s.m), 1e-9));
    CHECK(close_rel(s.pdf_o, pdf_o(method, p, s.o), 1e-9));
    CHECK(s.weight >= 0.0);
    if (method != Method::ndf)
        CHECK(s.weight <= 1.0 + 1e-12);  // G2/G1(i) (caps family), bounded even less
    if (dot(s.o, n) <= 0.0)
        CHECK(s.weight == 0.0);
}

}  // namespace

TEST_CASE("samples are unit, above the surface, and carry their recomputed pdfs")
{
    for (Method method : all_methods) {
        CAPTURE(std::string(method_name(method)));
        for (auto [ax, ay] : alpha_grid()) {
            std::vector<double> views = view_grid();
            if (handles_below_horizon(method))
                views.insert(views.end(), {100.0, 150.0});
            for (double theta : views) {
                CAPTURE(ax);
                CAPTURE(ay);
                CAPTURE(theta);
                const Params p = params(method, ax, ay, theta);
                for (double u1 : interior_uniforms())
                    for (double u2 : interior_uniforms())
                        check_sample(method, p, u1, u2);
            }
        }
    }
}

TEST_CASE("boundary uniforms give finite unit samples")
{
    const double top = 1.0 - 1.0 / 16777216.0;
    for (Method method : all_methods)
        for (double theta : {0.0, 45.0, 89.0})
            for (double u1 : {0.0, 0.25, top})
                for (double u2 : {0.0, 0.5, top}) {
                    CAPTURE(std::string(method_name(method)));
                    const Sample s = sample(method, params(method, 0.3, 0.6, theta), u1, u2);
                    CHECK(length(s.m) == doctest::Approx(1.0).epsilon(1e-12));
                    CHECK(s.m.z >= 0.0);
                    CHECK(std::isfinite(s.pdf_o));
                    CHECK(std::isfinite(s.weight));
                }
}

TEST_CASE("the caps family's pdf is the VNDF; the bounded one differs by (iz + t) / (k iz + t)")
{
    for (auto [ax, ay] : alpha_grid())
        for (double theta : {0.0, 30.0, 85.0}) {
            const Params p = params(Method::caps, ax, ay, theta);
            const double k = bounded_k(p.i, ax, ay), t = t_of(p.i, ax, ay);
            const Sample b = sample(Method::bounded, p, 0.3, 0.4);  // inside the bounded cap
            CHECK(close_rel(pdf_m(Method::caps, p, b.m), vndf_pdf(b.m, p.i, ax, ay), 1e-12));
            CHECK(close_rel(pdf_o(Method::caps, p, b.o), vndf_pdf(b.m, p.i, ax, ay) / (4.0 * dot(p.i, b.m)), 1e-9));
            CHECK(close_rel(pdf_o(Method::bounded, p, b.o) * (k * p.i.z + t), pdf_o(Method::caps, p, b.o) * (p.i.z + t),
                            1e-9));
        }
}

TEST_CASE("bounded with k = 1 (view below the horizon) is the caps sampler")
{
    for (double theta : {100.0, 150.0}) {
        const Params p = params(Method::caps, 0.4, 0.7, theta);
        for (double u : {0.1, 0.5, 0.9}) {
            const Sample b = sample(Method::bounded, p, u, 1.0 - u), c = sample(Method::caps, p, u, 1.0 - u);
            CHECK(length(b.m - c.m) < 1e-15);
            CHECK(b.pdf_o == c.pdf_o);
            CHECK(pdf_o(Method::bounded, p, c.o) == pdf_o(Method::caps, p, c.o));
        }
    }
}

TEST_CASE("recomputed pdfs vanish off the support")
{
    const Params p = params(Method::bounded, 0.8, 0.8, 40.0);
    const Vec3 below = normalize(-p.i + Vec3{0.0, 0.0, 0.05});  // near o = -i: in the caps support only
    CHECK(pdf_o(Method::bounded, p, below) == 0.0);
    CHECK(pdf_o(Method::caps, p, below) > 0.0);
    CHECK(pdf_o(Method::caps, p, -p.i) == 0.0);                               // i + o = 0
    CHECK(pdf_m(Method::caps, p, normalize({-p.i.x, -p.i.y, 0.05})) == 0.0);  // back-facing m
    CHECK(pdf_m(Method::ndf, p, normalize({-p.i.x, -p.i.y, 0.05})) > 0.0);
}
