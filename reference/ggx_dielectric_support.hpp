// ggx_dielectric_support.hpp - the edges on the sphere of directions where a rough dielectric's
// density of o and its BSDF jump or turn, and the point where the transmission peaks (internal helper
// of the integrals over o; ggx_bin_mass.hpp).
#pragma once

#include "ggx_bin_mass.hpp"

namespace ggxref::detail {

// For a view of either side (caller's frame; world space for caps_iso, tangent space otherwise).
Support dielectric_support(Method, const Params&, double eta);

}  // namespace ggxref::detail
