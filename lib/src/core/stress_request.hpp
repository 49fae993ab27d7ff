// stress_request.hpp - the checks of a stress request (Backend::stress) that
// both back ends make, and the planes of its inputs and outputs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ggxcl/backend.hpp"

namespace ggxcl::detail {

struct StressPlanes {
    std::uint64_t in, out;  // 10 and 10 planes; a dielectric's 12 and 11
};

// InvalidArgument unless a user sampler comes exactly with Method::user (and
// then no dielectric) and `in` holds the request's planes of `count` cases.
StressPlanes checked_stress(const StressRequest& request, const std::vector<float>& in, std::uint32_t count);

// The -D options of kernels/ggx_stress.cl for the request (the device's and the precision mode's
// options come on top); Method::user with its sampler's options.
std::string stress_defines(const StressRequest& request);

} // namespace ggxcl::detail
