// test_fresnel.cpp - the reference Fresnel terms against values known in
// closed form: normal incidence, the Brewster angle, total internal
// reflection, a conductor with k = 0 as a dielectric, Schlick's ends.
#include <doctest/doctest.h>

#include <cmath>

#include "ggx_reference.hpp"

using ggxref::fresnel_conductor;
using ggxref::fresnel_dielectric;
using ggxref::fresnel_schlick;

TEST_CASE("dielectric: normal incidence, Brewster's angle, grazing, the other side")
{
    for (double eta : {1.0 / 1.5, 1.33, 1.5, 2.42}) {
        const double r0 = std::pow((eta - 1.0) / (eta + 1.0), 2.0);
        CHECK(fresnel_dielectric(1.0, eta) == doctest::Approx(r0).epsilon(1e-12));
        CHECK(fresnel_dielectric(1e-9, eta) == doctest::Approx(1.0).epsilon(1e-6));  // grazing reflects all
    }
    // At Brewster's angle (tan theta = eta) the p wave is not reflected: F = rs^2 / 2, and there
    // rs = (c - eta ct) / (c + eta ct) with ct = sin theta = eta c (the refracted ray is perpendicular).
    const double eta = 1.5, c = 1.0 / std::sqrt(1.0 + eta * eta), ct = eta * c;
    const double rs = (c - eta * ct) / (c + eta * ct);
    CHECK(fresnel_dielectric(c, eta) == doctest::Approx(0.5 * rs * rs).epsilon(1e-12));
    // From below the same interface reads 1/eta: equal reflectance on both sides for matched angles.
    const double c_inside = std::sqrt(1.0 - (1.0 - c * c) / (eta * eta));
    CHECK(fresnel_dielectric(-c_inside, eta) == doctest::Approx(fresnel_dielectric(c, eta)).epsilon(1e-12));
}

TEST_CASE("dielectric: total internal reflection past the critical angle")
{
    const double eta = 1.5, critical = std::sqrt(1.0 - 1.0 / (eta * eta));  // cos of the critical angle, inside
    CHECK(fresnel_dielectric(-(critical - 1e-6), eta) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(fresnel_dielectric(-0.2, eta) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(fresnel_dielectric(-(critical + 1e-3), eta) < 1.0);
    CHECK(fresnel_dielectric(0.2, 1.0 / eta) == doctest::Approx(1.0).epsilon(1e-12));  // the same, eta < 1 above
}

TEST_CASE("conductor: normal incidence, k = 0 is a dielectric, between 0 and 1")
{
    for (auto [n, k] : {std::pair{0.143, 3.983}, {0.27, 2.78}, {1.12, 6.78}, {2.9, 3.1}}) {
        const double r0 = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
        CHECK(fresnel_conductor(1.0, n, k) == doctest::Approx(r0).epsilon(1e-12));
        for (double c = 0.0; c <= 1.0; c += 0.05) {
            const double f = fresnel_conductor(c, n, k);
            CHECK(f >= 0.0);
            CHECK(f <= 1.0 + 1e-12);
        }
        CHECK(fresnel_conductor(0.0, n, k) == doctest::Approx(1.0).epsilon(1e-12));
    }
    for (double c = 0.05; c <= 1.0; c += 0.05)
        CHECK(fresnel_conductor(c, 1.5, 0.0) == doctest::Approx(fresnel_dielectric(c, 1.5)).epsilon(1e-12));
}

TEST_CASE("Schlick: F0 at normal incidence, 1 at grazing")
{
    CHECK(fresnel_schlick(1.0, 0.04) == doctest::Approx(0.04));
    CHECK(fresnel_schlick(0.0, 0.04) == doctest::Approx(1.0));
    CHECK(fresnel_schlick(0.5, 0.04) == doctest::Approx(0.04 + 0.96 / 32.0));
}
