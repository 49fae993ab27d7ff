// test_histogram_fit.cpp - histograms binned on the device
// (Backend::histogram, ggx_histogram.cl, .comp and .hlsl) on the back end of
// GGX_TEST_API (backend_fixture.hpp; CTest runs it on OpenCL, on Vulkan in
// GLSL and on Vulkan in HLSL):
//   - every method's conductor histogram of o (1e6 samples, 24 x 48 bins of
//     equal solid angle) fits the reference's bin probabilities, and every
//     dielectric method's over the sphere with its invalid samples counted
//     apart, Sidak-corrected to a family level of 0.01 over all;
//   - every sample is counted once, none is NaN or Inf;
//   - negative controls: ndf's histogram fails caps' pdf, a dielectric's
//     fails another eta.
#include <doctest/doctest.h>

#include <string>

#include "backend_fixture.hpp"
#include "device_fixture.hpp"
#include "distribution_check.hpp"

namespace {

constexpr std::uint64_t dielectric_samples = 400000;

using ggxtest::chi_square_conductor;
using ggxtest::chi_square_dielectric;

// The p-value of the histogram of `sampled` against the bin probabilities of `tested`.
double p_value(ggxcl::Backend& backend, const ggxcl::SampleParams& sampled, const ggxcl::SampleParams& tested,
               std::uint64_t seed, std::uint64_t count)
{
    const ggxcl::Histogram h = backend.histogram(sampled, {seed, 0, count}, ggxtest::bins_z, ggxtest::bins_phi);
    CHECK(h.total() == count);
    CHECK(h.non_finite == 0);
    const auto expected =
        ggxbridge::bin_probabilities(tested.method, tested, ggxtest::bins_z, ggxtest::bins_phi, ggxcl::Field::o);
    return ggxbridge::histogram_fit(h, expected, tested.eta != 0.0f).p_value;
}

} // namespace

TEST_CASE("every method's device histogram fits its pdf, conductor and dielectric")
{
    ggxcl::Backend* backend = ggxtest::test_backend();
    if (!backend)
        return;
    int tests = 0;
    for (ggxcl::Method method : ggxcl::all_methods)
        tests += ggxcl::method_traits(method).dielectric ? 2 : 1;
    const double level = ggxref::sidak_level(ggxtest::family_level, tests);
    std::uint64_t seed = 500;
    for (ggxcl::Method method : ggxcl::all_methods) {
        const std::string name(ggxcl::method_name(method));
        const ggxcl::SampleParams c = chi_square_conductor(method);
        const double p = p_value(*backend, c, c, ++seed, ggxtest::chi_square_samples);
        INFO(name, " conductor: p = ", p, ", level ", level);
        CHECK(p > level);
        if (!ggxcl::method_traits(method).dielectric)
            continue;
        const ggxcl::SampleParams d = chi_square_dielectric(method, 1.5f);
        const double q = p_value(*backend, d, d, ++seed, dielectric_samples);
        INFO(name, " dielectric: p = ", q, ", level ", level);
        CHECK(q > level);
    }
}

TEST_CASE("negative controls: a device histogram fails a wrong distribution")
{
    ggxcl::Backend* backend = ggxtest::test_backend();
    if (!backend)
        return;
    CHECK(p_value(*backend, chi_square_conductor(ggxcl::Method::ndf), chi_square_conductor(ggxcl::Method::caps), 600,
                  ggxtest::chi_square_samples) < 1e-6);
    CHECK(p_value(*backend, chi_square_dielectric(ggxcl::Method::caps, 1.5f), chi_square_dielectric(ggxcl::Method::caps, 1.3f), 601,
                  dielectric_samples) < 1e-6);
}
