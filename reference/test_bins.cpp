// test_bins.cpp - per-bin probabilities: they add up to the normalization computed another way,
// are converged, and pass (or, for a sampler used out of its range, fail) a chi-square test
// against histograms of the reference samplers' own samples.
#include <doctest/doctest.h>

#include <chrono>
#include <string>

#include "ggx_quadrature.hpp"
#include "ggx_stats.hpp"
#include "ref_test_helpers.hpp"

using namespace reftest;

TEST_CASE("bins sum to integrate_pdf_o and take under 0.5 s at 32 x 64")
{
    double worst = 0.0, slowest = 0.0;
    for (const BinCase& c : hard_bin_cases()) {
        const auto start = std::chrono::steady_clock::now();
        const std::vector<double> bins = bin_probabilities(c.method, c.p, 32, 64);
        slowest = std::max(slowest, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        double sum = 0.0;
        for (double b : bins) {
            CHECK(b >= 0.0);
            sum += b;
        }
        CAPTURE(std::string(method_name(c.method)));
        CHECK(sum == doctest::Approx(integrate_pdf_o(c.method, c.p)).epsilon(1e-6));
        worst = std::max(worst, std::fabs(sum - 1.0));
    }
    MESSAGE("worst |sum of bins - 1| = " << worst << ", slowest 32x64 call " << slowest << " s");
}

TEST_CASE("bins are converged: default tolerance against a 1000 times tighter one")
{
    double worst_rel = 0.0;
    for (const BinCase& c : {hard_bin_cases()[0], hard_bin_cases()[6], hard_bin_cases()[8]}) {
        const std::vector<double> coarse = bin_probabilities(c.method, c.p, 16, 32);
        const std::vector<double> fine = bin_probabilities(c.method, c.p, 16, 32, 1e-11);
        for (size_t k = 0; k < fine.size(); ++k) {
            const double diff = std::fabs(coarse[k] - fine[k]);
            CHECK(diff <= std::max(1e-9, 1e-5 * fine[k]));
            if (fine[k] > 0.0)
                worst_rel = std::max(worst_rel, diff / fine[k]);
        }
    }
    MESSAGE("worst relative bin change = " << worst_rel);
}

TEST_CASE("reference samples pass chi-square against their own bins")
{
    const std::vector<BinCase> all = hard_bin_cases();
    const double level = sidak_level(1e-3, int(all.size()));
    for (const BinCase& c : all) {
        const ChiSquare r = chi_square_gof(sample_histogram(c.method, c.p, 200000, 16, 32, 2024, false),
                                           bin_probabilities(c.method, c.p, 16, 32));
        CAPTURE(std::string(method_name(c.method)));
        CAPTURE(r.statistic);
        CAPTURE(r.dof);
        CHECK(r.p_value > level);
        CHECK(r.bins_used > 40);  // the caps support at 150 degrees is a small cap
    }
}

TEST_CASE("negative control: heitz2017 below the horizon fails against the VNDF bins")
{
    const Params p = params(Method::caps, 0.5, 0.5, 120.0);
    const ChiSquare r = chi_square_gof(sample_histogram(Method::heitz2017, p, 200000, 16, 32, 2024, false),
                                       bin_probabilities(Method::caps, p, 16, 32));
    CHECK(r.p_value < 1e-12);
}

TEST_CASE("report: does heitz (2018 form) still give the VNDF below the horizon?")
{
    for (double theta : {120.0, 150.0})
        for (auto [ax, ay] : std::vector<std::pair<double, double>>{{0.5, 0.5}, {0.3, 0.9}}) {
            const Params p = params(Method::caps, ax, ay, theta);
            const ChiSquare r = chi_square_gof(sample_histogram(Method::heitz, p, 200000, 16, 32, 2024, false),
                                               bin_probabilities(Method::caps, p, 16, 32));
            MESSAGE("heitz vs caps pdf, alpha (" << ax << ", " << ay << "), theta " << theta << ": chi2 " << r.statistic
                                                 << ", dof " << r.dof << ", p " << r.p_value);
        }
}

TEST_CASE("near a view opposite the normal the bins of a unit view still sum to 1")
{
    // At 179.9 degrees the support of o is a cap 0.1 degrees wide about +z with the corner o = -i
    // on its edge; every bin of the top ring meets it. (Drift grows past 179.99: 6.5e-7 at 179.999.)
    for (Method m : {Method::heitz, Method::caps, Method::bounded})
        for (double alpha : {0.05, 0.3, 1.0})
            for (double theta : {179.0, 179.9, 179.99}) {
                CAPTURE(std::string(method_name(m)));
                CAPTURE(alpha);
                CAPTURE(theta);
                const std::vector<double> bins = bin_probabilities(m, params(m, alpha, alpha, theta), 16, 32);
                double sum = 0.0;
                for (double b : bins)
                    sum += b;
                CHECK(std::fabs(sum - 1.0) <= 1e-8);
            }
}
