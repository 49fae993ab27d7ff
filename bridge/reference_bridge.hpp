// reference_bridge.hpp - from the library's types to the double-precision
// reference's (reference/): the method of the same name and the parameters
// as the device sees them.
#pragma once

#include <ggxcl/ggxcl.hpp>

#include "ggx_reference.hpp"

namespace ggxapp {

// The reference's method of the same name (the two enums are independent).
ggxref::Method reference_method(ggxcl::Method method);

// The (already normalized) float parameters as doubles.
ggxref::Params reference_params(const ggxcl::SampleParams& params);

} // namespace ggxapp
