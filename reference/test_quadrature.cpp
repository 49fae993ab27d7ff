// test_quadrature.cpp - normalization of every pdf, accepted and bounded-cap masses, directional
// albedo, each against a closed form or an independent integration.
#include <doctest/doctest.h>

#include <string>

#include "ggx_adaptive.hpp"
#include "ggx_quadrature.hpp"
#include "ref_test_helpers.hpp"

using namespace reftest;
using ggxref::detail::adaptive_gauss;

TEST_CASE("every pdf_o integrates to 1 (alpha 0.01..2, anisotropy 1:10, views 0..85, 100, 150)")
{
    double worst = 0.0;
    for (Method method : all_methods)
        for (auto [ax, ay] : alpha_grid()) {
            std::vector<double> views = view_grid();
            if (handles_below_horizon(method))
                views.insert(views.end(), {100.0, 150.0});
            for (double theta : views) {
                CAPTURE(std::string(method_name(method)));
                CAPTURE(ax);
                CAPTURE(ay);
                CAPTURE(theta);
                const double mass = integrate_pdf_o(method, params(method, ax, ay, theta));
                CHECK(mass == doctest::Approx(1.0).epsilon(1e-6));
                worst = std::max(worst, std::fabs(mass - 1.0));
            }
        }
    MESSAGE("worst |integrate_pdf_o - 1| = " << worst);
}

TEST_CASE("accepted mass: alpha = 1 at normal incidence, caps wastes half and bounded nothing")
{
    const Params p{1.0, 1.0, {0.0, 0.0, 1.0}};
    CHECK(integrate_pdf_o_upper(Method::caps, p) == doctest::Approx(0.5).epsilon(1e-10));
    CHECK(integrate_pdf_o_upper(Method::ndf, p) == doctest::Approx(0.5).epsilon(1e-10));
    CHECK(integrate_pdf_o_upper(Method::bounded, p) == doctest::Approx(1.0).epsilon(1e-10));
}

TEST_CASE("accepted mass for alpha > 1 (k < 0): bounded wastes less than with k = 0, nothing at normal incidence")
{
    // alpha 1.5: k = 0 (a clamped to 1) kept t / (iz + t) of the caps pdf, the bound keeps
    // 1 - (1 - k) iz / (iz + t); the wasted fractions are 1 - upper(caps) / kept.
    const Params p = params(Method::bounded, 1.5, 1.5, 52.0);
    const double t = t_of(p.i, p.ax, p.ay), upper_caps = integrate_pdf_o_upper(Method::caps, p);
    const double wasted_k0 = 1.0 - upper_caps * (p.i.z + t) / t;
    const double wasted = 1.0 - integrate_pdf_o_upper(Method::bounded, p);
    MESSAGE("alpha 1.5, 52 degrees: caps wastes " << 1.0 - upper_caps << ", k = 0 " << wasted_k0 << ", k = "
                                                   << bounded_k(p.i, p.ax, p.ay) << " " << wasted);
    CHECK(wasted_k0 == doctest::Approx(0.343757).epsilon(1e-5));
    CHECK(wasted == doctest::Approx(0.324224).epsilon(1e-5));
    CHECK(integrate_pdf_o_upper(Method::bounded, params(Method::bounded, 1.5, 1.5, 0.0)) ==
          doctest::Approx(1.0).epsilon(1e-10));
    CHECK(integrate_pdf_o_upper(Method::bounded, params(Method::bounded, 4.0, 4.0, 0.0)) ==
          doctest::Approx(1.0).epsilon(1e-10));
}

TEST_CASE("the bounded cap keeps all of the upper hemisphere: upper(bounded) = upper(caps) / (1 - r)")
{
    for (auto [ax, ay] : alpha_grid())
        for (double theta : view_grid()) {
            const Params p = params(Method::bounded, ax, ay, theta);
            const double k = bounded_k(p.i, ax, ay), t = t_of(p.i, ax, ay);
            const double kept = 1.0 - (1.0 - k) * p.i.z / (p.i.z + t);
            CAPTURE(ax);
            CAPTURE(ay);
            CAPTURE(theta);
            CHECK(bounded_cap_mass_of_caps(p) == doctest::Approx(kept).epsilon(1e-9));
            CHECK(integrate_pdf_o_upper(Method::bounded, p) ==
                  doctest::Approx(integrate_pdf_o_upper(Method::caps, p) / kept).epsilon(1e-9));
        }
    CHECK(bounded_cap_mass_of_caps(params(Method::caps, 0.5, 0.5, 120.0)) == doctest::Approx(1.0).epsilon(1e-9));
}

TEST_CASE("albedo: closed form 1 - ln 2 at alpha = 1, normal incidence; -> 1 as alpha -> 0")
{
    CHECK(albedo({1.0, 1.0, {0.0, 0.0, 1.0}}) == doctest::Approx(1.0 - std::log(2.0)).epsilon(1e-12));
    const double e3 = albedo({1e-3, 1e-3, {0.0, 0.0, 1.0}}), e2 = albedo({1e-2, 1e-2, {0.0, 0.0, 1.0}});
    CHECK(e3 < 1.0);
    CHECK(e3 > 1.0 - 1e-5);
    CHECK(e2 < e3);
    CHECK(albedo(params(Method::caps, 1e-3, 1e-3, 60.0)) > 0.9999);
}

TEST_CASE("albedo never exceeds the accepted VNDF mass (its weight G2/G1 is at most 1)")
{
    for (auto [ax, ay] : alpha_grid())
        for (double theta : view_grid()) {
            const Params p = params(Method::caps, ax, ay, theta);
            CHECK(albedo(p) <= integrate_pdf_o_upper(Method::caps, p) + 1e-12);
            CHECK(albedo(p) > 0.0);
        }
}

TEST_CASE("albedo agrees with a plain quadrature over o where the lobe is wide")
{
    for (auto [ax, ay] : std::vector<std::pair<double, double>>{{0.5, 0.5}, {0.4, 1.0}, {1.5, 1.5}})
        for (double theta : {0.0, 50.0, 80.0}) {
            const Vec3 i = direction(theta, 0.6);
            auto meridian = [&](double phi) {
                auto f = [&](double th) {
                    const Vec3 o{std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi), std::cos(th)};
                    return brdf_cos(i, o, ax, ay) * std::sin(th);
                };
                return adaptive_gauss(f, 0.0, 0.5 * pi, {1e-13, 1e-11});
            };
            const double plain = adaptive_gauss(meridian, 0.0, 2.0 * pi, {1e-12, 1e-10});
            CAPTURE(theta);
            CHECK(albedo({ax, ay, i}) == doctest::Approx(plain).epsilon(1e-7));
        }
}
