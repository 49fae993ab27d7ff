// distribution_check.hpp - chi-square machinery the distribution tests
// share: histogram device samples of o in bins of equal solid angle over
// (phi, cos theta), expected counts from the reference pdf integrated over
// each bin, and the Sidak-corrected level.
#pragma once

#include "device_fixture.hpp"

namespace ggxtest {

constexpr int bins_z = 24;
constexpr int bins_phi = 48;
constexpr std::uint64_t chi_square_samples = 1000000;
constexpr double family_level = 0.01;   // significance over all configurations of a method
constexpr int configs_per_method = 20;

// Histogram of the reflected directions the device draws for `sampled`.
std::vector<std::uint64_t> device_histogram(ggxref::Method sampled, const ggxref::Params& params, std::uint64_t seed,
                                            std::uint64_t count = chi_square_samples,
                                            ggxcl::Precision precision = ggxcl::Precision::precise,
                                            ggxcl::Sequence sequence = ggxcl::Sequence::philox);

// Goodness of fit of a histogram to `tested`'s pdf at `params`.
ggxref::ChiSquare fit(const std::vector<std::uint64_t>& histogram, ggxref::Method tested,
                      const ggxref::Params& params);

// Per-configuration level after Sidak correction over a method's configurations.
double per_config_level();

// The request the device-histogram suites draw (test_histogram_fit, tests/vulkan): alpha
// (0.35, 0.7) (0.35 where the method is isotropic), view (0.6, 0.3, 0.5) normalized; and the same
// surface as a dielectric of relative index eta.
ggxcl::SampleParams chi_square_conductor(ggxcl::Method method);
ggxcl::SampleParams chi_square_dielectric(ggxcl::Method method, float eta);

} // namespace ggxtest
