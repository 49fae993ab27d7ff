// test_agreement.cpp - heitz, heitz2017, caps and caps-iso are four ways to
// draw the same VNDF: their device samples must agree in distribution
// (two-sample chi-square homogeneity tests, Sidak-corrected), and ndf must
// not agree with them (negative control).
#include <doctest/doctest.h>

#include "distribution_check.hpp"

namespace {

using ggxref::Method;

const Method vndf_methods[] = {Method::heitz, Method::heitz2017, Method::caps, Method::caps_iso};

std::vector<ggxtest::Config> agreement_grid()
{
    std::vector<ggxtest::Config> grid;
    for (double alpha : {0.1, 0.4, 1.2})
        for (double theta : {10.0, 70.0})
            grid.push_back({ggxtest::make_params(alpha, alpha, theta), ""});
    return grid;
}

} // namespace

TEST_CASE("heitz, heitz2017, caps and caps-iso agree in distribution")
{
    std::vector<ggxtest::Config> grid = agreement_grid();
    const int pairs = 6;  // 4 methods, pairwise
    double level = ggxref::sidak_level(ggxtest::family_level, int(grid.size()) * pairs);
    std::uint64_t seed = 500;
    for (const ggxtest::Config& config : grid) {
        std::vector<std::vector<std::uint64_t>> histograms;
        for (Method method : vndf_methods)
            histograms.push_back(ggxtest::device_histogram(method, config.params, ++seed));
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b) {
                ggxref::ChiSquare result = ggxref::chi_square_homogeneity(histograms[a], histograms[b]);
                CAPTURE(ggxtest::describe(config.params));
                CAPTURE(ggxref::method_name(vndf_methods[a]));
                CAPTURE(ggxref::method_name(vndf_methods[b]));
                CAPTURE(result.statistic);
                CHECK(result.p_value > level);
            }
    }
}

TEST_CASE("heitz and caps agree for anisotropic roughness")
{
    double level = ggxref::sidak_level(ggxtest::family_level, 3);
    std::uint64_t seed = 700;
    for (double theta : {0.0, 40.0, 80.0}) {
        ggxref::Params params = ggxtest::make_params(0.1, 0.5, theta, 60.0);
        ggxref::ChiSquare result = ggxref::chi_square_homogeneity(
            ggxtest::device_histogram(Method::heitz, params, ++seed), ggxtest::device_histogram(Method::caps, params, ++seed));
        CAPTURE(theta);
        CHECK(result.p_value > level);
    }
}

TEST_CASE("negative control: ndf and caps do not agree in distribution")
{
    ggxref::Params params = ggxtest::make_params(0.4, 0.4, 70.0);
    ggxref::ChiSquare result = ggxref::chi_square_homogeneity(ggxtest::device_histogram(Method::ndf, params, 11),
                                                              ggxtest::device_histogram(Method::caps, params, 12));
    CHECK(result.p_value < ggxtest::per_config_level());
}
