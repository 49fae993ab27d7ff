// reference_bridge.hpp - the one map between the library's types and the
// double-precision reference's (reference/), used by the apps and the tests
// alike: the same method either way, and the parameters as the
// device sees them.  The reference keeps its own enum and math (that is its
// point); only this bridge knows both.
#pragma once

#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "ggx_reference.hpp"
#include "ggx_stats.hpp"

namespace ggxbridge {

// The same method in the other enum (the same id and name).
ggxref::Method reference_method(ggxcl::Method method);
ggxcl::Method library_method(ggxref::Method method);

// The float parameters as doubles, the view and normal scaled to unit length in
// double: a unit float vector is off unit by up to ~1e-7, and the reference's
// formulas take unit vectors (near a view opposite the normal, where 1 - iz^2 is
// small, a float-rounded view made its bins sum to 1.0175 at 179.9 degrees).
ggxref::Params reference_params(const ggxcl::SampleParams& params);
ggxref::Vec3 reference_direction(const ggxcl::Vec3& direction);  // unit in double
// The reference's parameters as the library's, rounded to float, in `precision`.
ggxcl::SampleParams library_params(ggxref::Method method, const ggxref::Params& params,
                                   ggxcl::Precision precision = ggxcl::Precision::precise);

// The probability of each bin of a device histogram of `direction` (o or m)
// under `method`'s pdf at the (normalized) params: what `ggx histogram` and
// the Python Sampler.histogram test their counts against.  With params.eta
// (a dielectric) the directions o over the whole sphere, both lobes.
std::vector<double> bin_probabilities(ggxcl::Method method, const ggxcl::SampleParams& params, int bins_z,
                                      int bins_phi, ggxcl::Field direction);

// The chi-square test of a device histogram against bin_probabilities: its bins, and for a
// dielectric one more category, the invalid samples (Histogram::invalid), whose probability is
// what the bins leave of 1.
ggxref::ChiSquare histogram_fit(const ggxcl::Histogram& histogram, const std::vector<double>& probabilities,
                                bool dielectric);

// The chi-square of a user sampler's histogram: each bin's kept samples against `kept` (within
// `error`, empty for none), and directions that are not finite against nothing.  Its discarded
// samples (Histogram::invalid: o below the horizon with weight 0) are one more category expecting
// what the bins leave of 1 `with_discarded` (a claimed distribution, a density over the sphere);
// without, they are left out and the test is of the kept samples' shape alone (a user's pdf, whose
// normalization and mass below the horizon the integral and reach checks judge).
ggxref::ChiSquare user_histogram_fit(const ggxcl::Histogram& counts, const std::vector<double>& kept,
                                     const std::vector<double>& error, bool with_discarded);

} // namespace ggxbridge
