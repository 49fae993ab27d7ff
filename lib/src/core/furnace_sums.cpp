// furnace_sums.cpp - the furnace's partial sums added on the host, and
// FurnaceSums' estimates (furnace_sums.hpp).
#include "furnace_sums.hpp"

#include <algorithm>
#include <cmath>

namespace ggxcl {

namespace detail {

std::size_t furnace_sum_planes(const SampleParams& params)
{
    return params.eta != 0.0f ? 3 : 2;
}

bool add_furnace_partial_sums(const float* host, std::size_t items, std::size_t planes, FurnaceSums& total,
                              bool keep_any)
{
    FurnaceSums sums = total;
    bool finite = true;
    for (std::size_t g = 0; g < items; ++g) {
        const float reflected = planes > 2 ? host[2 * items + g] : 0.0f;
        finite = finite && std::isfinite(host[g]) && std::isfinite(host[items + g]) && std::isfinite(reflected);
        sums.sum += host[g];
        sums.sum_of_squares += host[items + g];
        sums.reflected_sum += reflected;
    }
    if (finite || keep_any)
        total = sums;
    return finite;
}

} // namespace detail

} // namespace ggxcl
