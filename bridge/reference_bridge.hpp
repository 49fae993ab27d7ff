// reference_bridge.hpp - the one map between the library's types and the
// double-precision reference's (reference/), used by the apps and the tests
// alike: the method of the same name either way, and the parameters as the
// device sees them.  The reference keeps its own enum and math (that is its
// point); only this bridge knows both.
#pragma once

#include <ggxcl/ggxcl.hpp>

#include "ggx_reference.hpp"

namespace ggxbridge {

// The method of the same name in the other enum.
ggxref::Method reference_method(ggxcl::Method method);
ggxcl::Method library_method(ggxref::Method method);

// The (already normalized) float parameters as doubles.
ggxref::Params reference_params(const ggxcl::SampleParams& params);
// The reference's parameters as the library's, rounded to float, in `precision`.
ggxcl::SampleParams library_params(ggxref::Method method, const ggxref::Params& params,
                                   ggxcl::Precision precision = ggxcl::Precision::precise);

} // namespace ggxbridge
