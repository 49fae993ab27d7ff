// distribution_check.cpp - histograms of device samples and chi-square fits.
#include "distribution_check.hpp"

namespace ggxtest {

std::vector<std::uint64_t> device_histogram(ggxref::Method sampled, const ggxref::Params& params, std::uint64_t seed,
                                            std::uint64_t count, ggxcl::Precision precision, ggxcl::Sequence sequence)
{
    ggxcl::SampleSet s = device_samples(sampled, params, seed, count, {ggxcl::Field::o}, precision, sequence);
    return histogram_of(s.o, s.count, bins_z, bins_phi);
}

ggxref::ChiSquare fit(const std::vector<std::uint64_t>& histogram, ggxref::Method tested, const ggxref::Params& params)
{
    return ggxref::chi_square_gof_float(histogram, ggxref::bin_probabilities(tested, params, bins_z, bins_phi));
}

double per_config_level()
{
    return ggxref::sidak_level(family_level, configs_per_method);
}

} // namespace ggxtest
