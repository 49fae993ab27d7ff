// test_stats.cpp - direction binning, chi-square goodness of fit and homogeneity on multinomial
// draws with known probabilities (calibration and power), pooling, and the Sidak level.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "ggx_stats.hpp"

using namespace ggxref;

namespace {

// 60 bins with a geometric spread of probabilities, some too small for 5 expected counts.
std::vector<double> probabilities()
{
    std::vector<double> p;
    double sum = 0.0;
    for (int k = 0; k < 60; ++k)
        sum += p.emplace_back(std::pow(0.9, k));
    for (double& x : p)
        x /= sum;
    return p;
}

std::vector<uint64_t> draw(const std::vector<double>& p, int n, uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::discrete_distribution<int> pick(p.begin(), p.end());
    std::vector<uint64_t> h(p.size(), 0);
    for (int k = 0; k < n; ++k)
        ++h[size_t(pick(rng))];
    return h;
}

}  // namespace

TEST_CASE("histogram_directions uses the bins of bin_probabilities")
{
    const float x[] = {1.0f, 1e-7f, -1.0f, 0.0f, 0.6f, 0.0f, 1.0f, NAN};
    const float y[] = {0.0f, 0.0f, -0.0f, -1.0f, -0.1f, 0.0f, -1e-7f, 0.0f};
    const float z[] = {0.0f, 1.0000001f, 0.0f, 0.0f, -0.79f, -1.0f, 0.0f, 0.0f};
    const auto h = histogram_directions(x, y, z, 8, 4, 8);
    CHECK(h.size() == 32);
    CHECK(h[2 * 8 + 0] == 1);  // z = 0 -> row 2, phi = 0 -> column 0
    CHECK(h[3 * 8 + 0] == 1);  // z > 1 clamped to the top row
    CHECK(h[2 * 8 + 4] == 1);  // phi = pi
    CHECK(h[2 * 8 + 6] == 1);  // phi = 3 pi / 2
    CHECK(h[0 * 8 + 7] == 1);  // z = -0.79, phi just below 2 pi
    CHECK(h[0 * 8 + 0] == 1);  // the south pole
    CHECK(h[2 * 8 + 7] == 1);  // phi = 2 pi - 1e-7
    uint64_t total = 0;
    for (uint64_t c : h)
        total += c;
    CHECK(total == 7);  // the NaN direction is not counted
}

TEST_CASE("goodness of fit is calibrated on correct draws and pools sparse bins")
{
    const std::vector<double> p = probabilities();
    int rejected = 0;
    for (uint64_t seed = 1; seed <= 200; ++seed) {
        const ChiSquare r = chi_square_gof(draw(p, 2000, seed), p);
        CHECK(r.bins_used < 60);
        CHECK(r.dof == r.bins_used - 1);
        rejected += r.p_value < 0.05;
    }
    CHECK(rejected >= 2);  // binomial(200, 0.05): mean 10
    CHECK(rejected <= 22);
}

TEST_CASE("goodness of fit rejects a wrong distribution and impossible counts")
{
    const std::vector<double> p = probabilities();
    std::vector<double> q = p;
    q[3] *= 1.1;  // 10% more in one bin (unnormalized: the test normalizes)
    CHECK(chi_square_gof(draw(q, 200000, 7), p).p_value < 1e-6);
    CHECK(chi_square_gof(draw(p, 200000, 7), p).p_value > 1e-3);
    std::vector<double> zero = p;
    zero.push_back(0.0);
    std::vector<uint64_t> h = draw(p, 200000, 7);
    h.push_back(0);
    CHECK(chi_square_gof(h, zero).p_value > 1e-3);
    h.back() = 1;  // one count where the pdf is zero
    CHECK(chi_square_gof(h, zero).p_value < 1e-12);
    CHECK(chi_square_gof(std::vector<uint64_t>(61, 0), zero).p_value == 0.0);  // nothing to test
}

TEST_CASE("homogeneity accepts two draws of one distribution and rejects two different ones")
{
    const std::vector<double> p = probabilities();
    std::vector<double> q = p;
    q[0] *= 0.9;
    int rejected = 0;
    for (uint64_t seed = 1; seed <= 200; ++seed) {
        const ChiSquare r = chi_square_homogeneity(draw(p, 3000, seed), draw(p, 5000, seed + 1000));
        CHECK(r.dof == r.bins_used - 1);
        rejected += r.p_value < 0.05;
    }
    CHECK(rejected >= 2);
    CHECK(rejected <= 22);
    CHECK(chi_square_homogeneity(draw(p, 300000, 1), draw(q, 300000, 2)).p_value < 1e-6);
    CHECK(chi_square_homogeneity(draw(p, 100, 1), std::vector<uint64_t>(60, 0)).p_value == 0.0);
}

TEST_CASE("sidak level")
{
    CHECK(sidak_level(0.05, 1) == doctest::Approx(0.05));
    CHECK(sidak_level(0.05, 10) == doctest::Approx(1.0 - std::pow(0.95, 0.1)).epsilon(1e-12));
    CHECK(sidak_level(1e-12, 1000000) == doctest::Approx(1e-18).epsilon(1e-6));
}

TEST_CASE("chi_square_gof_float leaves out a few counts past a support edge, and no more")
{
    const std::vector<double> p = {0.25, 0.25, 0.5, 0.0};
    const std::vector<uint64_t> clean = {250000, 250000, 500000, 0};
    std::vector<uint64_t> one_stray = clean, many_stray = clean;
    one_stray[3] = 1;
    many_stray[3] = 1000;
    CHECK(chi_square_gof(one_stray, p).p_value == 0.0);  // the strict test rejects any count there
    CHECK(chi_square_gof_float(one_stray, p).p_value == doctest::Approx(chi_square_gof(clean, p).p_value));
    CHECK(chi_square_gof_float(many_stray, p).p_value == 0.0);
}

TEST_CASE("no pass without evidence: one cell, a probability not finite")
{
    // Every sample in one bin: no degree of freedom is left, so nothing was tested.
    const ggxref::ChiSquare one = chi_square_gof({1000, 0}, {1.0, 0.0});
    CHECK(one.dof == 0);
    CHECK(one.p_value == 0.0);
    for (double bad : {std::nan(""), double(INFINITY), -double(INFINITY)}) {
        const ggxref::ChiSquare r = chi_square_gof({500, 500}, {0.5, bad});
        CHECK(r.dof == 0);
        CHECK(r.p_value == 0.0);
        CHECK(std::isnan(r.statistic));
        CHECK(chi_square_gof_float({500, 500}, {bad, 0.5}).p_value == 0.0);
    }
}

TEST_CASE("chi_square_gof with expectation errors: a known quadrature error is not a misfit, a larger bias is")
{
    // The expectation is off by 0.4 % in two bins of 1e6 samples (4000 counts, ~9 sigma): the plain
    // test rejects it, the test told of that error accepts it, and a bias ten times the stated error
    // is still rejected.
    const std::vector<double> p = {0.25, 0.25, 0.25, 0.25}, biased = {0.254, 0.246, 0.25, 0.25};
    const std::vector<uint64_t> h = draw(p, 1000000, 3);
    const std::vector<double> errors = {0.004, 0.004, 0.0, 0.0}, small = {0.0004, 0.0004, 0.0, 0.0};
    CHECK(chi_square_gof(h, biased).p_value < 1e-12);
    CHECK(chi_square_gof(h, biased, errors).p_value > 0.01);
    CHECK(chi_square_gof(h, biased, small).p_value < 1e-9);
    CHECK(chi_square_gof(h, p, {}).p_value == doctest::Approx(chi_square_gof(h, p).p_value));
}
