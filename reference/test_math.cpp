// test_math.cpp - the shared GGX quantities against identities computed independently: NDF
// normalization and projected area by plain quadrature over m, Smith relations, the bounded k.
#include <doctest/doctest.h>

#include "ggx_adaptive.hpp"
#include "ref_test_helpers.hpp"

using namespace reftest;
using ggxref::detail::adaptive_gauss;

namespace {

// int over the hemisphere of f(m) dw_m in plain polar coordinates of m (no stretching).
template <class F> double integrate_hemisphere(const F& f)
{
    auto meridian = [&](double phi) {
        auto g = [&](double th) {
            return f(Vec3{std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi), std::cos(th)}) * std::sin(th);
        };
        return adaptive_gauss(g, 0.0, 0.5 * pi, {1e-12, 1e-10});
    };
    return adaptive_gauss(meridian, 0.0, 2.0 * pi, {1e-11, 1e-9});
}

}  // namespace

TEST_CASE("D is normalized: int D(m) mz dm = 1")
{
    for (auto [ax, ay] : std::vector<std::pair<double, double>>{{0.3, 0.3}, {0.25, 0.8}, {1.0, 1.0}, {2.0, 0.6}}) {
        CAPTURE(ax);
        CAPTURE(ay);
        const double mass = integrate_hemisphere([&](const Vec3& m) { return D(m, ax, ay) * m.z; });
        CHECK(mass == doctest::Approx(1.0).epsilon(1e-8));
    }
}

TEST_CASE("projected area: int max(0, i.m) D(m) dm = sigma(i), also below the horizon")
{
    for (auto [ax, ay] : std::vector<std::pair<double, double>>{{0.4, 0.4}, {0.3, 0.9}, {1.5, 0.7}})
        for (double theta : {0.0, 40.0, 80.0, 110.0, 160.0}) {
            const Vec3 i = direction(theta, 0.9);
            CAPTURE(theta);
            const double area =
                integrate_hemisphere([&](const Vec3& m) { return std::max(0.0, dot(i, m)) * D(m, ax, ay); });
            CHECK(area == doctest::Approx(projected_area(i, ax, ay)).epsilon(1e-6));
            CHECK(projected_area(i, ax, ay) == doctest::Approx(0.5 * (i.z + t_of(i, ax, ay))).epsilon(1e-12));
        }
}

TEST_CASE("projected area is cancellation-free below the horizon")
{
    const Vec3 i = normalize({1e-9, 0.0, -1.0});
    const double sigma = projected_area(i, 0.5, 0.5);
    CHECK(sigma > 0.0);
    CHECK(sigma == doctest::Approx(0.25 * 0.25e-18).epsilon(1e-6));  // (a i_x)^2 / (2 (t - iz)) ~ a^2 1e-18 / 4
}

TEST_CASE("Smith relations: G1 = 1/(1 + Lambda), Lambda(-w) = 1 + Lambda(w), G2 = 1/(1 + Li + Lo)")
{
    const double ax = 0.35, ay = 0.8;
    for (double theta : {5.0, 45.0, 89.0})
        for (double phi : {0.0, 1.0, 2.5}) {
            const Vec3 w = direction(theta, phi), o = direction(90.0 - 0.9 * theta, phi + 2.0);
            CHECK(G1(w, ax, ay) == doctest::Approx(1.0 / (1.0 + lambda(w, ax, ay))).epsilon(1e-13));
            CHECK(lambda(-w, ax, ay) == doctest::Approx(1.0 + lambda(w, ax, ay)).epsilon(1e-13));
            CHECK(lambda(w, ax, ay) == doctest::Approx(0.5 * (t_of(w, ax, ay) / w.z - 1.0)).epsilon(1e-9));
            CHECK(G2_height_correlated(w, o, ax, ay) ==
                  doctest::Approx(1.0 / (1.0 + lambda(w, ax, ay) + lambda(o, ax, ay))).epsilon(1e-13));
            CHECK(G2_separable(w, o, ax, ay) == doctest::Approx(G1(w, ax, ay) * G1(o, ax, ay)));
            CHECK(G2_height_correlated(w, o, ax, ay) >= G2_separable(w, o, ax, ay) - 1e-15);
            CHECK(G2_height_correlated(w, -o, ax, ay) == 0.0);
        }
}

TEST_CASE("isotropic world-space forms equal the tangent forms for n = z and rotate with n")
{
    const double a = 0.37;
    const Rotation R = rotation_to(normalize({0.3, -0.5, 0.2}));
    for (double theta : {0.0, 30.0, 70.0}) {
        const Vec3 m = direction(theta, 0.4), i = direction(theta + 10.0, 2.0);
        const Vec3 z{0, 0, 1};
        CHECK(D_iso(m, z, a) == doctest::Approx(D(m, a, a)).epsilon(1e-13));
        CHECK(t_iso(i, z, a) == doctest::Approx(t_of(i, a, a)).epsilon(1e-13));
        CHECK(D_iso(R.apply(m), R.cz, a) == doctest::Approx(D(m, a, a)).epsilon(1e-12));
        CHECK(G2_height_correlated_iso(R.apply(i), R.apply(m), R.cz, a) ==
              doctest::Approx(G2_height_correlated(i, m, a, a)).epsilon(1e-12));
    }
}

TEST_CASE("bounded k oracles")
{
    const Vec3 i = direction(40.0, 0.3);
    CHECK(bounded_k(i, 1.0, 1.0) == 0.0);         // a = 1
    CHECK(bounded_k(i, 1e-4, 0.5) > 1.0 - 1e-7);  // k -> 1 as alpha -> 0
    CHECK(bounded_k(i, 1e-4, 0.5) <= 1.0);
    for (double a : {0.05, 0.3, 0.7, 0.99}) {
        const double k = bounded_k(i, a, 2.0 * a);
        CHECK(k > 0.0);
        CHECK(k < 1.0);
    }
    // k < 0 for a > 1, and k > -1: the cap z > -k vz is never empty and k iz + t > 0.
    for (double a : {1.01, 1.5, 3.0, 100.0, 1e6})
        for (double theta : {0.0, 40.0, 89.9}) {
            const Vec3 v = direction(theta, 0.3);
            const double k = bounded_k(v, a, 1.5 * a), t = t_of(v, a, 1.5 * a);
            CAPTURE(a);
            CAPTURE(theta);
            CHECK(k < 0.0);
            CHECK(k > -1.0);
            CHECK(-k * v.z / t < 1.0);
            CHECK(k * v.z + t > 0.0);
        }
    CHECK(bounded_k(i, 1.5, 2.0) == bounded_k(i, 2.0, 1.5));  // a = min(ax, ay)
    // k decreases with roughness, through 0 at a = 1.
    CHECK(bounded_k(i, 0.2, 0.2) > bounded_k(i, 0.5, 0.5));
    CHECK(bounded_k(i, 0.9, 0.9) > bounded_k(i, 1.5, 1.5));
    CHECK(bounded_k(i, 1.5, 1.5) > bounded_k(i, 3.0, 3.0));
    // a > 1: (1 - a^2)/(1 + a^2) at normal incidence, -> 0 at grazing views (no 0/0 at iz = 0).
    CHECK(bounded_k({0.0, 0.0, 1.0}, 2.0, 3.0) == doctest::Approx(-3.0 / 5.0).epsilon(1e-15));
    CHECK(bounded_k({1.0, 0.0, 0.0}, 2.0, 3.0) == 0.0);
    CHECK(std::fabs(bounded_k(direction(90.0 - 1e-6, 0.3), 2.0, 3.0)) < 1e-15);
}

TEST_CASE("bounded k is exact: 1 - k <= R(phi) on the projected horizon (supplement Eq. 1), with equality "
          "for isotropic alpha")
{
    // ohat_z of the horizon direction at azimuth phi is (R(phi) - 1) ih.z; the cap holds it iff
    // R(phi) >= 1 - k. R is written here from Eq. 1, apart from bounded_k's closed form.
    auto R = [](const Vec3& i, double ax, double ay, double phi) {
        const double cx = i.x + std::cos(phi), cy = i.y + std::sin(phi);
        return (cx * cx + cy * cy + i.z * i.z) / (cx * cx / (ax * ax) + cy * cy / (ay * ay) + i.z * i.z);
    };
    const std::pair<double, double> alphas[] = {{1.5, 1.5}, {3.0, 3.0}, {1.3, 2.0}, {2.0, 1.3},
                                                {0.3, 0.3}, {0.5, 1.7}, {1.0, 4.0}};
    for (auto [ax, ay] : alphas)
        for (double theta : {0.0, 20.0, 52.0, 80.0, 89.0, 89.99})
            for (double azimuth : {0.3, 2.0, 4.0}) {
                const Vec3 i = direction(theta, azimuth);
                const double k = bounded_k(i, ax, ay);
                double least = 1e300;
                for (int j = 0; j < 3600; ++j)
                    least = std::min(least, R(i, ax, ay, 2.0 * pi * (j + 0.5) / 3600.0));
                CAPTURE(ax);
                CAPTURE(ay);
                CAPTURE(theta);
                CAPTURE(azimuth);
                CHECK(1.0 - k <= least * (1.0 + 1e-14));
                if (ax == ay && theta > 0.0) {
                    // attained at the azimuth of ih (a <= 1) or of -ih (a > 1)
                    const double at = ax <= 1.0 ? azimuth : azimuth + pi;
                    CHECK(R(i, ax, ay, at) == doctest::Approx(1.0 - k).epsilon(1e-12));
                }
            }
}
