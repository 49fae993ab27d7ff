// test_dielectric_bins.cpp - the dielectric's bin probabilities: they add up to the probability of a
// valid sample integrated over normals instead of directions (and to its closed form at normal
// incidence), are converged, take well under a second at 24 x 48, and pass (or, with another index,
// fail) a chi-square test against histograms of the reference's own dielectric samples.
#include <doctest/doctest.h>

#include <chrono>
#include <string>

#include "ref_test_helpers.hpp"

using namespace reftest;

namespace {

struct DielectricCase {
    Method method;
    Params p;
    double eta;
};

// Small and large alpha, anisotropy, grazing views and views below, indices near 1 and far from it,
// a rotated normal.
std::vector<DielectricCase> hard_cases()
{
    return {{Method::ndf, params(Method::ndf, 0.1, 0.1, 80.0), 1.05},
            {Method::ndf, params(Method::ndf, 0.5, 0.15, 120.0), 2.4},
            {Method::heitz, params(Method::heitz, 0.05, 0.3, 60.0), 1.5},
            {Method::heitz2017, params(Method::heitz2017, 1.0, 1.0, 45.0), 1.0 / 1.5},
            {Method::caps, params(Method::caps, 0.1, 0.1, 120.0), 1.5},
            {Method::caps, params(Method::caps, 0.5, 0.5, 0.0), 1.05},
            {Method::caps_iso, rotated(0.3, 70.0, normalize({0.3, -0.5, 0.8})), 1.5},
            {Method::caps_iso, rotated(0.6, 130.0, normalize({-0.7, 0.1, -0.2})), 2.4}};
}

double sum(const std::vector<double>& v)
{
    double s = 0.0;
    for (double x : v)
        s += x;
    return s;
}

// Histogram of the valid samples' o among `count` dielectric samples (Philox u1, u2, u3); `valid`
// returns how many there were.
std::vector<uint64_t> dielectric_histogram(const DielectricCase& c, size_t count, int nz, int nphi, size_t& valid)
{
    std::vector<float> x, y, z;
    for (size_t k = 0; k < count; ++k) {
        const auto u = uniforms(7, k);
        const Sample s = dielectric_sample(c.method, c.p, c.eta, false, u[0], u[1], lobe_uniform_philox(7, k));
        if (s.pdf_o > 0.0) {
            x.push_back(float(s.o.x));
            y.push_back(float(s.o.y));
            z.push_back(float(s.o.z));
        }
    }
    valid = x.size();
    return histogram_directions(x.data(), y.data(), z.data(), valid, nz, nphi);
}

}  // namespace

TEST_CASE("dielectric bins sum to the valid probability integrated over normals (1e-6)")
{
    double worst = 0.0;
    for (double eta : {1.5, 1.0 / 1.5, 1.05, 2.4})
        for (double alpha : {0.1, 0.5, 1.0})
            for (double theta : {0.0, 45.0, 80.0, 120.0}) {
                const Params p = params(Method::caps, alpha, alpha, theta);
                const double bins = sum(dielectric_bin_probabilities(Method::caps, p, eta, 8, 16));
                const double normals = dielectric_valid_probability(Method::caps, p, eta);
                CAPTURE(eta);
                CAPTURE(alpha);
                CAPTURE(theta);
                CHECK(bins == doctest::Approx(normals).epsilon(1e-6));
                CHECK(normals <= 1.0);
                worst = std::max(worst, std::fabs(bins - normals));
            }
    for (const DielectricCase& c : hard_cases()) {
        CAPTURE(std::string(method_name(c.method)));
        const double normals = dielectric_valid_probability(c.method, c.p, c.eta);
        CHECK(sum(dielectric_bin_probabilities(c.method, c.p, c.eta, 8, 16)) == doctest::Approx(normals).epsilon(1e-6));
    }
    MESSAGE("worst |sum of bins - valid probability| on the caps grid = " << worst);
}

TEST_CASE("at normal incidence with eta < 1/sqrt(2) exactly the normals tilted under 45 degrees give valid samples")
{
    // Beyond 45 degrees the reflection falls below the horizon, and i.m < 1/sqrt(2) < sqrt(1 - eta^2)
    // reflects totally; under it no refraction rises above the horizon. NDF and VNDF agree at i = n:
    // P(tan theta_m < 1) = 1 / (1 + alpha^2).
    for (Method method : {Method::ndf, Method::caps})
        for (double alpha : {0.1, 0.5, 1.0, 1.7})
            for (double eta : {1.0 / 1.5, 0.5})
                CHECK(dielectric_valid_probability(method, params(method, alpha, alpha, 0.0), eta) ==
                      doctest::Approx(1.0 / (1.0 + alpha * alpha)).epsilon(1e-10));
}

TEST_CASE("dielectric bins are converged and take well under a second at 24 x 48")
{
    double slowest = 0.0, worst = 0.0;
    for (const DielectricCase& c : {hard_cases()[0], hard_cases()[4], hard_cases()[7]}) {
        const auto start = std::chrono::steady_clock::now();
        const std::vector<double> coarse = dielectric_bin_probabilities(c.method, c.p, c.eta, 24, 48);
        slowest = std::max(slowest, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        const std::vector<double> fine = dielectric_bin_probabilities(c.method, c.p, c.eta, 24, 48, 1e-11);
        for (size_t k = 0; k < fine.size(); ++k) {
            CHECK(coarse[k] >= 0.0);
            CHECK(std::fabs(coarse[k] - fine[k]) <= std::max(1e-9, 1e-5 * fine[k]));
            worst = std::max(worst, std::fabs(coarse[k] - fine[k]));
        }
    }
    MESSAGE("slowest 24 x 48 call " << slowest << " s; worst bin change at a 1000 times tighter tolerance " << worst);
    CHECK(slowest < 2.0);
}

TEST_CASE("reference dielectric samples pass chi-square against the bins; the count of valid ones fits")
{
    const std::vector<DielectricCase> all = hard_cases();
    const double level = sidak_level(1e-3, int(all.size()));
    const size_t count = 200000;
    for (const DielectricCase& c : all) {
        CAPTURE(std::string(method_name(c.method)));
        CAPTURE(c.eta);
        size_t valid = 0;
        const std::vector<double> bins = dielectric_bin_probabilities(c.method, c.p, c.eta, 16, 32);
        const ChiSquare r = chi_square_gof(dielectric_histogram(c, count, 16, 32, valid), bins);
        CAPTURE(r.statistic);
        CAPTURE(r.dof);
        CHECK(r.p_value > level);
        CHECK(r.bins_used > 25);  // an index near 1 narrows the transmission to a few bins
        const double q = sum(bins), sd = std::sqrt(count * q * (1.0 - q));
        CHECK(std::fabs(double(valid) - count * q) < 5.0 * sd + 1.0);
    }
}

TEST_CASE("negative control: dielectric samples fail against the bins of an index 5% off")
{
    for (const DielectricCase& c : {hard_cases()[2], hard_cases()[5]}) {
        size_t valid = 0;
        const ChiSquare r = chi_square_gof(dielectric_histogram(c, 200000, 16, 32, valid),
                                           dielectric_bin_probabilities(c.method, c.p, c.eta * 1.05, 16, 32));
        CHECK(r.p_value < 1e-12);
    }
}
