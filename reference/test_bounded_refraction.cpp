// test_bounded_refraction.cpp - the share of a rough dielectric's transmission on normals the bounded
// cap never draws: at normal incidence (isotropic alpha <= 1) the cap keeps exactly the normals tilted
// under 45 degrees, checked against a one-dimensional integral over the tilt; it is positive at grazing
// rough views and small for smooth ones.
#include <doctest/doctest.h>

#include "ggx_adaptive.hpp"
#include "ref_test_helpers.hpp"

using namespace reftest;

namespace {

// At i = n the VNDF is D(m) mz; a normal of tilt th refracts with weight G2 / G1(n) = G2 (no masking
// of the view), and the integrand is azimuthally symmetric: int over th of D cos th (1 - F) G2 sin th.
double transmitted_by_tilt(double alpha, double eta, double lo, double hi)
{
    auto f = [&](double th) {
        const Vec3 i{0.0, 0.0, 1.0}, m{std::sin(th), 0.0, std::cos(th)};
        const double c = m.z, cos_t = std::sqrt(1.0 - (1.0 - c * c) / (eta * eta));
        const Vec3 o = (-1.0 / eta) * i + (c / eta - cos_t) * m;
        const double g2 = G2_height_correlated(i, {o.x, o.y, -o.z}, alpha, alpha);
        return D(m, alpha, alpha) * c * (1.0 - fresnel_dielectric(c, eta)) * g2 * std::sin(th);
    };
    return ggxref::detail::adaptive_gauss(f, lo, hi, {1e-15, 1e-12});
}

}  // namespace

TEST_CASE("bounded loses the refractions of normals tilted past 45 degrees at normal incidence")
{
    for (double alpha : {0.1, 0.5, 1.0})
        for (double eta : {1.33, 2.4}) {
            const double kept = transmitted_by_tilt(alpha, eta, 0.0, 0.25 * pi);
            const double lost = transmitted_by_tilt(alpha, eta, 0.25 * pi, 0.5 * pi);
            CAPTURE(alpha);
            CAPTURE(eta);
            const double share = bounded_lost_transmission(params(Method::caps, alpha, alpha, 0.0), eta);
            CHECK(share == doctest::Approx(lost / (kept + lost)).epsilon(1e-8));
            CHECK(share > 0.0);
        }
}

TEST_CASE("bounded's lost transmission: positive at grazing rough views, small for smooth ones")
{
    CHECK(bounded_lost_transmission(params(Method::caps, 0.8, 0.8, 85.0), 1.5) > 1e-3);
    CHECK(bounded_lost_transmission(params(Method::caps, 1.0, 1.0, 60.0), 1.5) > 0.1);
    CHECK(bounded_lost_transmission(params(Method::caps, 0.3, 0.3, 120.0), 1.5) > 1e-3);  // from below
    CHECK(bounded_lost_transmission(params(Method::caps, 0.05, 0.05, 30.0), 1.5) < 1e-2);
    for (double theta : {0.0, 45.0, 85.0}) {
        const double s = bounded_lost_transmission(params(Method::caps, 0.4, 0.2, theta), 2.4);
        CHECK(s > 0.0);
        CHECK(s < 1.0);
    }
}
