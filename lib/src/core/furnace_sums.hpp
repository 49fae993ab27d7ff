// furnace_sums.hpp - the host's half of the fused white-furnace estimator,
// shared by the OpenCL (sampler_furnace.cpp) and Vulkan (vulkan_sampler.cpp)
// back ends: the planes of partial sums a launch writes, and their sum in
// double in work-item order (ggx_furnace.cl, ggx_furnace_shader.h).
#pragma once

#include <cstddef>

#include "ggxcl/params.hpp"
#include "ggxcl/results.hpp"

namespace ggxcl::detail {

// The planes of partial sums a launch writes: weights, squares, and a dielectric's reflected weights.
std::size_t furnace_sum_planes(const SampleParams& params);

// The partial sums of one launch (`planes` planes of `items`) added in
// double, in work-item order, to `total`; false, with `total` unchanged,
// if one of them is not finite, unless `keep_any` adds them anyway.
bool add_furnace_partial_sums(const float* host, std::size_t items, std::size_t planes, FurnaceSums& total,
                              bool keep_any);

} // namespace ggxcl::detail
