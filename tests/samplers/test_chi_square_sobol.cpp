// test_chi_square_sobol.cpp - goodness of fit of device samples drawn from
// the Owen-scrambled Sobol points (SampleParams::sequence = sobol) to each
// method's pdf: 2^20 samples of o (a whole (0, 20, 2)-net) per configuration
// on the 20 configurations of test_chi_square, bins of equal solid angle with
// sparse bins pooled, Sidak-corrected to a family level of 0.01 per method;
// bounded also where both alphas exceed 1.  A net spreads its points more
// evenly than independent draws, so under a correct mapping the statistic
// runs below its chi-square law (p-values near 1): the test still rejects a
// wrong distribution, as the negative controls show with Sobol points.
#include <doctest/doctest.h>

#include <algorithm>

#include "distribution_check.hpp"

namespace {

using ggxref::Method;

constexpr std::uint64_t net_samples = std::uint64_t(1) << 20;

void check_fits(Method method, const std::vector<ggxtest::Config>& grid, std::uint64_t seed)
{
    double level = ggxref::sidak_level(ggxtest::family_level, int(grid.size()));
    double lowest = 1.0, highest = 0.0;
    for (const ggxtest::Config& config : grid) {
        std::vector<double> expected =
            ggxref::bin_probabilities(method, config.params, ggxtest::bins_z, ggxtest::bins_phi);
        ggxref::ChiSquare result = ggxref::chi_square_gof_float(
            ggxtest::device_histogram(method, config.params, ++seed, net_samples, ggxcl::Precision::precise,
                                      ggxcl::Sequence::sobol),
            expected);
        CAPTURE(config.label);
        CAPTURE(result.statistic);
        CAPTURE(result.dof);
        CHECK(result.bins_used > 10);
        CHECK(result.p_value > level);
        lowest = std::min(lowest, result.p_value);
        highest = std::max(highest, result.p_value);
    }
    MESSAGE(std::string(ggxref::method_name(method)) << " with Sobol points: p-values of " << grid.size()
                                                     << " configurations in [" << lowest << ", " << highest
                                                     << "], level " << level);
}

void check_fits(Method method)
{
    check_fits(method, ggxtest::distribution_grid(method), 3000);
}

// `sampled`'s Sobol-point directions against `tested`'s pdf.
ggxref::ChiSquare fit_sobol(Method sampled, Method tested, const ggxref::Params& params)
{
    return ggxtest::fit(ggxtest::device_histogram(sampled, params, 17, net_samples, ggxcl::Precision::precise,
                                                  ggxcl::Sequence::sobol),
                        tested, params);
}

} // namespace

TEST_CASE("chi-square with Sobol points: ndf") { check_fits(Method::ndf); }
TEST_CASE("chi-square with Sobol points: heitz") { check_fits(Method::heitz); }
TEST_CASE("chi-square with Sobol points: heitz2017") { check_fits(Method::heitz2017); }
TEST_CASE("chi-square with Sobol points: caps") { check_fits(Method::caps); }
TEST_CASE("chi-square with Sobol points: caps-iso") { check_fits(Method::caps_iso); }
TEST_CASE("chi-square with Sobol points: bounded") { check_fits(Method::bounded); }
TEST_CASE("chi-square with Sobol points: bounded where both alphas exceed 1")
{
    check_fits(Method::bounded, ggxtest::rough_bounded_grid(), 7000);
}

TEST_CASE("negative controls with Sobol points: ndf against the VNDF pdf, bounded against k = 1")
{
    ggxref::ChiSquare ndf = fit_sobol(Method::ndf, Method::caps, ggxtest::make_params(0.5, 0.5, 60.0));
    MESSAGE("ndf (Sobol) against the VNDF pdf: chi2 " << ndf.statistic << " on " << ndf.dof << " dof, p "
                                                      << ndf.p_value);
    CHECK(ndf.p_value < ggxtest::per_config_level());
    ggxref::ChiSquare bounded = fit_sobol(Method::bounded, Method::caps, ggxtest::make_params(0.5, 0.5, 30.0));
    MESSAGE("bounded (Sobol) against k = 1: chi2 " << bounded.statistic << " on " << bounded.dof << " dof, p "
                                                   << bounded.p_value);
    CHECK(bounded.p_value < ggxtest::per_config_level());
}
