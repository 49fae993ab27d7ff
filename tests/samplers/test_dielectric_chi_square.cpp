// test_dielectric_chi_square.cpp - rough dielectrics (SampleParams::eta):
// the directions every exact method draws, reflected and transmitted, over
// the whole sphere against the reference's bin probabilities
// (reference/ggx_dielectric.hpp), with the invalid samples as one more
// category; views from above and below, eta above and below 1 and near 1,
// anisotropic roughness, a tilted normal for caps-iso.  Sidak-corrected over
// each method's configurations.  Negative controls: a wrong eta, the
// transmission's Jacobian without eta^2, and the other side's index for a
// view from inside are each rejected.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "dielectric_grid.hpp"
#include "distribution_check.hpp"

namespace {

using ggxref::Method;
using ggxtest::DielectricConfig;

constexpr int nz = 24, nphi = 48;
constexpr std::uint64_t samples = 400000;

ggxcl::Histogram device_histogram(Method method, const DielectricConfig& c, std::uint64_t seed)
{
    return ggxtest::sampler().histogram(ggxtest::dielectric_params(method, c), {seed, 0, samples}, nz, nphi);
}

double p_value(const ggxcl::Histogram& h, const std::vector<double>& expected)
{
    return ggxbridge::histogram_fit(h, expected, true).p_value;
}

void check_method(Method method)
{
    const std::vector<DielectricConfig> grid = ggxtest::dielectric_grid(method);
    const double level = ggxref::sidak_level(ggxtest::family_level, int(grid.size()));
    double lowest = 1.0;
    std::uint64_t seed = 500;
    for (const DielectricConfig& c : grid) {
        const ggxcl::Histogram h = device_histogram(method, c, ++seed);
        const std::vector<double> expected =
            ggxref::dielectric_bin_probabilities(method, c.params, c.eta, nz, nphi);
        const ggxref::ChiSquare fit = ggxbridge::histogram_fit(h, expected, true);
        CAPTURE(c.label);
        CAPTURE(fit.statistic);
        CAPTURE(fit.dof);
        CHECK(h.non_finite == 0);
        CHECK(fit.bins_used > 20);  // eta 1.05: the transmission lies within a few bins
        CHECK(fit.p_value > level);
        lowest = std::min(lowest, fit.p_value);
    }
    MESSAGE(std::string(ggxref::method_name(method)) << ": lowest p-value " << lowest << " of " << grid.size()
                                        << " configurations, level " << level);
}

// The bins of a view above the surface with the transmitted half (z < 0) scaled by `factor`.
std::vector<double> transmission_scaled(std::vector<double> bins, double factor)
{
    for (int b = 0; b < nz / 2 * nphi; ++b)
        bins[std::size_t(b)] *= factor;
    return bins;
}

} // namespace

TEST_CASE("dielectric chi-square: ndf") { check_method(Method::ndf); }
TEST_CASE("dielectric chi-square: heitz") { check_method(Method::heitz); }
TEST_CASE("dielectric chi-square: heitz2017") { check_method(Method::heitz2017); }
TEST_CASE("dielectric chi-square: caps") { check_method(Method::caps); }
TEST_CASE("dielectric chi-square: caps-iso") { check_method(Method::caps_iso); }

TEST_CASE("dielectric chi-square: negative controls are rejected")
{
    const Method method = Method::caps;
    DielectricConfig above{ggxtest::make_params(0.4, 0.4, 50.0), 1.5, false, "above"};
    const ggxcl::Histogram h = device_histogram(method, above, 77);
    const std::vector<double> right = ggxref::dielectric_bin_probabilities(method, above.params, 1.5, nz, nphi);
    CHECK(p_value(h, right) > 1e-3);
    SUBCASE("a wrong eta")
    {
        CHECK(p_value(h, ggxref::dielectric_bin_probabilities(method, above.params, 1.4, nz, nphi)) < 1e-9);
    }
    SUBCASE("the transmission's Jacobian without eta^2")
    {
        CHECK(p_value(h, transmission_scaled(right, 1.0 / (1.5 * 1.5))) < 1e-9);
    }
    SUBCASE("the index of the other side (1/eta) for a view from inside")
    {
        DielectricConfig inside{ggxtest::make_params(0.4, 0.4, 25.0), 1.0f / 1.5f, false, "inside"};
        const ggxcl::Histogram hi = device_histogram(method, inside, 78);
        const double eta = inside.eta;
        CHECK(p_value(hi, ggxref::dielectric_bin_probabilities(method, inside.params, eta, nz, nphi)) > 1e-3);
        CHECK(p_value(hi, ggxref::dielectric_bin_probabilities(method, inside.params, 1.0 / eta, nz, nphi)) < 1e-9);
    }
}
