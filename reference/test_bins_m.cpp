// test_bins_m.cpp - per-bin probabilities of the microfacet normal m: they add up to 1, vanish below
// the surface, agree with an independent integration in the standard space, are converged, and
// pass (or, for another sampler's normals, fail) a chi-square test against histograms of the
// reference samplers' own normals.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "ggx_quadrature.hpp"
#include "ggx_standard_space.hpp"
#include "ggx_stats.hpp"
#include "ref_test_helpers.hpp"

using namespace reftest;
using ggxref::detail::Local;

namespace {

// The bin z in [z0, z1], phi in [phi0, phi1] of m, carried to the standard space (tangent space):
// m = normalize(ax msx, ay msy, msz) keeps the quadrant of the azimuth with tan phi_s = (ax/ay)
// tan phi, and on the meridian phi_s, tan theta = l tan theta_s, l = |(ax cos phi_s, ay sin phi_s)|.
double standard_azimuth(const Params& p, double phi)
{
    const double s = std::atan2(p.ax * std::sin(phi), p.ay * std::cos(phi));
    return s + 2.0 * pi * std::round((phi - s) / (2.0 * pi));  // |phi - s| < pi / 2
}

double standard_polar(const Local& L, double z, double phi_s)
{
    const double l = std::hypot(L.ax * std::cos(phi_s), L.ay * std::sin(phi_s));
    return z <= 0.0 ? 0.5 * pi : std::atan2(std::sqrt(1.0 - z * z), l * z);  // msz > 0 iff mz > 0
}

// The same bin integrated over ms: pdf_m dw_m is smooth there but for the closed-form visibility
// and bounded-cap cuts of each meridian. An independent check, not a replacement: its outer
// integral over phi_s does not cut where those curves meet the bin's latitudes.
double standard_bin(Method method, const Params& p, double z0, double z1, double phi0, double phi1)
{
    const Local L = ggxref::detail::tangent_problem(p);
    const double k = method == Method::bounded && p.i.z > 0.0 ? bounded_k(p.i, p.ax, p.ay) : 1.0;
    auto density = [&](const Vec3&, const Vec3& m) { return pdf_m(method, p, m); };
    auto meridian = [&](double phi_s) {
        const double c = std::cos(phi_s), s = std::sin(phi_s);
        const double a = standard_polar(L, z1, phi_s), b = standard_polar(L, z0, phi_s);
        std::vector<double> cuts = ggxref::detail::cuts_visible(L, phi_s);
        if (k < 1.0)
            for (double x : ggxref::detail::cuts_bounded_cap(L, phi_s, k))
                cuts.push_back(x);
        cuts.erase(std::remove_if(cuts.begin(), cuts.end(), [&](double x) { return !(x > a && x < b); }), cuts.end());
        cuts.insert(cuts.end(), {a, b});
        std::sort(cuts.begin(), cuts.end());
        auto f = [&](double th) { return ggxref::detail::standard_integrand(L, density, th, c, s); };
        double sum = 0.0;
        for (size_t j = 0; j + 1 < cuts.size(); ++j)
            sum += ggxref::detail::adaptive_gauss(f, cuts[j], cuts[j + 1], {1e-17, 1e-13});
        return sum;
    };
    return ggxref::detail::adaptive_gauss(meridian, standard_azimuth(p, phi0), standard_azimuth(p, phi1),
                                          {1e-16, 1e-12});
}

}  // namespace

TEST_CASE("m-bins sum to 1, vanish below the surface, and take under 0.5 s at 32 x 64")
{
    double worst = 0.0, slowest = 0.0;
    for (const BinCase& c : hard_bin_cases()) {
        const auto start = std::chrono::steady_clock::now();
        const std::vector<double> bins = bin_probabilities_m(c.method, c.p, 32, 64);
        slowest = std::max(slowest, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        CAPTURE(std::string(method_name(c.method)));
        double sum = 0.0;
        for (size_t k = 0; k < bins.size(); ++k) {
            CHECK(bins[k] >= 0.0);
            if (c.method != Method::caps_iso && k < bins.size() / 2)
                CHECK(bins[k] == 0.0);  // mz <= 0
            sum += bins[k];
        }
        CHECK(sum == doctest::Approx(1.0).epsilon(1e-12));
        worst = std::max(worst, std::fabs(sum - 1.0));
    }
    MESSAGE("worst |sum of m-bins - 1| = " << worst << ", slowest 32x64 call " << slowest << " s");
}

TEST_CASE("m-bins agree with an integration over the standard space, per bin to 1e-10")
{
    const int nz = 16, nphi = 32;
    double worst = 0.0;
    for (const int index : {0, 1, 2, 3, 5, 8, 9, 12}) {
        const BinCase c = hard_bin_cases()[index];
        const std::vector<double> bins = bin_probabilities_m(c.method, c.p, nz, nphi);
        CAPTURE(std::string(method_name(c.method)));
        for (int jz = nz / 2; jz < nz; ++jz)
            for (int jp = 0; jp < nphi; ++jp) {
                const double expected = standard_bin(c.method, c.p, -1.0 + 2.0 * jz / nz, -1.0 + 2.0 * (jz + 1) / nz,
                                                     2.0 * pi * jp / nphi, 2.0 * pi * (jp + 1) / nphi);
                const double diff = std::fabs(bins[size_t(jz) * nphi + jp] - expected);
                CHECK(diff <= 1e-10);
                worst = std::max(worst, diff);
            }
    }
    MESSAGE("worst |m-bin - standard-space bin| = " << worst);
}

TEST_CASE("m-bins are converged: default tolerance against a 10^4 times tighter one")
{
    double worst = 0.0;
    for (const int index : {6, 10}) {
        const BinCase c = hard_bin_cases()[index];
        const std::vector<double> coarse = bin_probabilities_m(c.method, c.p, 16, 32);
        const std::vector<double> fine = bin_probabilities_m(c.method, c.p, 16, 32, 1e-12);
        for (size_t k = 0; k < fine.size(); ++k) {
            CHECK(std::fabs(coarse[k] - fine[k]) <= 1e-11);
            worst = std::max(worst, std::fabs(coarse[k] - fine[k]));
        }
    }
    MESSAGE("worst |m-bin change| = " << worst);
}

TEST_CASE("reference normals pass chi-square against their own m-bins")
{
    const std::vector<BinCase> all = hard_bin_cases();
    const double level = sidak_level(1e-3, int(all.size()));
    for (const BinCase& c : all) {
        const ChiSquare r =
            chi_square_gof(sample_histogram(c.method, c.p, 200000, 16, 32, 2025, true), bin_probabilities_m(c.method, c.p, 16, 32));
        CAPTURE(std::string(method_name(c.method)));
        CAPTURE(r.statistic);
        CAPTURE(r.dof);
        CHECK(r.p_value > level);
        CHECK(r.bins_used > 40);
    }
}

TEST_CASE("negative controls: NDF-sampled normals fail against the VNDF m-bins, bounded ones against caps")
{
    const Params p = params(Method::caps, 0.5, 0.5, 60.0);
    const ChiSquare ndf =
        chi_square_gof(sample_histogram(Method::ndf, p, 200000, 16, 32, 2025, true), bin_probabilities_m(Method::caps, p, 16, 32));
    CHECK(ndf.p_value < 1e-12);
    const Params q = params(Method::caps, 0.3, 0.3, 30.0);
    const ChiSquare bounded = chi_square_gof(sample_histogram(Method::bounded, q, 200000, 16, 32, 2025, true),
                                             bin_probabilities_m(Method::caps, q, 16, 32));
    CHECK(bounded.p_value < 1e-12);
}
