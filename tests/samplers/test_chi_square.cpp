// test_chi_square.cpp - goodness of fit of device samples to each method's
// pdf: 1e6 samples of o per configuration, 20 configurations per method,
// each in both precision modes, bins of equal solid angle in
// (phi, cos theta) with sparse bins pooled, Sidak-corrected over the 40
// tests to a family level of 0.01 per method; bounded also on 6
// configurations where both alphas exceed 1 (k < 0), Sidak over those.
// Negative controls show the same test rejects wrong distributions.
#include <doctest/doctest.h>

#include <algorithm>
#include <iterator>

#include "distribution_check.hpp"

namespace {

using ggxref::Method;

// Sidak over the configurations of `grid` in every precision mode.
void check_fits(Method method, const std::vector<ggxtest::Config>& grid, std::uint64_t seed)
{
    const int modes = int(std::size(ggxtest::all_precisions));
    double level = ggxref::sidak_level(ggxtest::family_level, int(grid.size()) * modes);
    double lowest = 1.0, highest = 0.0;
    for (const ggxtest::Config& config : grid) {
        std::vector<double> expected =
            ggxref::bin_probabilities(method, config.params, ggxtest::bins_z, ggxtest::bins_phi);
        for (ggxcl::Precision precision : ggxtest::all_precisions) {
            ggxref::ChiSquare result = ggxref::chi_square_gof_float(
                ggxtest::device_histogram(method, config.params, ++seed, ggxtest::chi_square_samples, precision),
                expected);
            CAPTURE(config.label);
            CAPTURE(ggxcl::precision_name(precision));
            CAPTURE(result.statistic);
            CAPTURE(result.dof);
            CHECK(result.bins_used > 10);
            CHECK(result.p_value > level);
            lowest = std::min(lowest, result.p_value);
            highest = std::max(highest, result.p_value);
        }
    }
    MESSAGE(std::string(ggxref::method_name(method)) << ": p-values of " << grid.size() << " configurations x "
                                                     << modes << " precision modes in [" << lowest << ", " << highest
                                                     << "], level " << level);
}

void check_fits(Method method)
{
    std::vector<ggxtest::Config> grid = ggxtest::distribution_grid(method);
    REQUIRE(grid.size() == ggxtest::configs_per_method);
    check_fits(method, grid, 1000);
}

} // namespace

TEST_CASE("chi-square: ndf samples follow the ndf pdf") { check_fits(Method::ndf); }
TEST_CASE("chi-square: heitz samples follow the VNDF pdf") { check_fits(Method::heitz); }
TEST_CASE("chi-square: heitz2017 samples follow the VNDF pdf") { check_fits(Method::heitz2017); }
TEST_CASE("chi-square: caps samples follow the VNDF pdf") { check_fits(Method::caps); }
TEST_CASE("chi-square: caps-iso samples follow the VNDF pdf in world space") { check_fits(Method::caps_iso); }
TEST_CASE("chi-square: bounded samples follow the bounded pdf") { check_fits(Method::bounded); }

TEST_CASE("chi-square: bounded samples follow the bounded pdf where both alphas exceed 1 (k < 0)")
{
    check_fits(Method::bounded, ggxtest::rough_bounded_grid(), 5000);
}

TEST_CASE("negative control: NDF-sampled directions are rejected against the VNDF pdf")
{
    ggxref::Params params = ggxtest::make_params(0.5, 0.5, 60.0);
    ggxref::ChiSquare result = ggxtest::fit(ggxtest::device_histogram(Method::ndf, params, 7), Method::caps, params);
    MESSAGE("ndf against the VNDF pdf: chi2 " << result.statistic << " on " << result.dof << " dof, p " << result.p_value);
    CHECK(result.p_value < ggxtest::per_config_level());
}

TEST_CASE("negative control: bounded samples are rejected against the unbounded (k = 1) pdf")
{
    ggxref::Params params = ggxtest::make_params(0.5, 0.5, 30.0);
    ggxref::ChiSquare result = ggxtest::fit(ggxtest::device_histogram(Method::bounded, params, 8), Method::caps, params);
    MESSAGE("bounded against k = 1: chi2 " << result.statistic << " on " << result.dof << " dof, p " << result.p_value);
    CHECK(result.p_value < ggxtest::per_config_level());
}

TEST_CASE("negative control: a sampler with alpha_x and alpha_y swapped is rejected")
{
    ggxref::Params params = ggxtest::make_params(0.2, 0.6, 45.0, 30.0);
    ggxref::Params swapped = params;
    std::swap(swapped.ax, swapped.ay);
    for (Method method : {Method::heitz, Method::caps, Method::bounded}) {
        ggxref::ChiSquare result = ggxtest::fit(ggxtest::device_histogram(method, swapped, 9), method, params);
        MESSAGE(std::string(ggxref::method_name(method)) << " with swapped alphas: chi2 " << result.statistic << " on "
                                                         << result.dof << " dof, p " << result.p_value);
        CHECK(result.p_value < ggxtest::per_config_level());
    }
}
