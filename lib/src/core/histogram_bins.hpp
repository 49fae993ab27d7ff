// histogram_bins.hpp - what a histogram request may ask of a device, for
// every back end: its bins and their counters fit the device's local
// (shared) memory, at most 2^16 phi bins, and it bins o or m.
#pragma once

#include <cstddef>

#include "ggxcl/fields.hpp"

namespace ggxcl::detail {

// Throws InvalidArgument ("bins", "bins_phi", "direction") naming the limit;
// `local_bytes` is the device's local memory per work-group.
void check_histogram_bins(int bins_z, int bins_phi, Field direction, std::size_t local_bytes);

} // namespace ggxcl::detail
