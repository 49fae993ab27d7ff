// user_fit_checks.hpp - what `ggx histogram --sampler` tests of a user
// sampler's histogram and weights: the chi-square against its own pdf and
// against the distribution it claims (ggxbridge::user_histogram_fit), the pdf's integral with its error bar, whether the pdf holds
// mass where the sampler never goes, and the mean weight against the albedo.
#pragma once

#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "ggx_stats.hpp"
#include "pdf_bins.hpp"
#include "user_checks.hpp"

namespace ggxapp {

// A chi-square's verdict: p >= level, and evidence (a degree of freedom, finite expectations),
// else it fails with the reason; `where_zero`: the samples in bins the pdf gives 0 (and directions
// that are not finite), named in the summary.
HistogramCheck chi_square_check(const std::string& name, const ggxref::ChiSquare& fit, double level,
                                std::uint64_t where_zero);
// The samples in bins where `kept` is not positive, and those whose direction is not finite.
std::uint64_t samples_where_zero(const ggxcl::Histogram& counts, const std::vector<double>& kept);

// The pdf integrates to 1 over the sphere, or to 1 minus the discarded fraction where the pdf is 0
// on what it discards; the tolerance is the quadrature's error bar (and the discarded fraction's
// noise), a few 1e-4 where the pdf is smooth.
HistogramCheck integral_check(const ggxbridge::BinIntegrals& own, const ggxcl::Histogram& counts);

// The pdf's mass where the sampler goes: no bin expecting 20 samples or more gets none, and below
// the horizon the pdf holds what the sampler discards there (or nothing: a pdf of 0 where it
// discards); mass beyond the sampler's reach is named.
HistogramCheck reach_check(const ggxbridge::BinIntegrals& own, const ggxcl::Histogram& counts);

// The mean weight of `samples` against the albedo the BRDF gives at params' view (the reference's
// quadrature): a weight that belongs to another distribution than the samples fails, naming the
// ratio.
HistogramCheck weight_check(const ggxcl::SampleSet& samples, const ggxcl::SampleParams& params);

} // namespace ggxapp
