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

ggxcl::SampleParams chi_square_conductor(ggxcl::Method method)
{
    ggxcl::SampleParams p;
    p.method = method;
    p.alpha_x = 0.35f;
    p.alpha_y = ggxcl::method_traits(method).isotropic_only ? 0.35f : 0.7f;
    p.view = ggxcl::unit_vector({0.6f, 0.3f, 0.5f});
    return p;
}

ggxcl::SampleParams chi_square_dielectric(ggxcl::Method method, float eta)
{
    ggxcl::SampleParams p = chi_square_conductor(method);
    p.eta = eta;
    return p;
}

} // namespace ggxtest
