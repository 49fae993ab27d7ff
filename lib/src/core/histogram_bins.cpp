// histogram_bins.cpp - the checks of a histogram request (histogram_bins.hpp).
#include "histogram_bins.hpp"

#include <string>

#include "ggxcl/error.hpp"

namespace ggxcl::detail {

namespace {
constexpr int max_phi_bins = 1 << 16;
}

void check_histogram_bins(int bins_z, int bins_phi, Field direction, std::size_t local_bytes)
{
    const std::size_t most = local_bytes / sizeof(std::uint32_t) - 2;  // and the two counters after the bins
    if (bins_z < 1 || bins_phi < 1 || std::size_t(bins_z) * bins_phi > most)
        throw InvalidArgument("bins", std::to_string(bins_z) + "x" + std::to_string(bins_phi),
                              "at least 1x1 and at most " + std::to_string(most) +
                                  " bins in all (the device's local memory)");
    if (bins_phi > max_phi_bins)
        throw InvalidArgument("bins_phi", std::to_string(bins_phi),
                              "1 .. " + std::to_string(max_phi_bins) +
                                  " (the device's phi bin is exact while half a bin exceeds its angle's 1e-5 rad error)");
    if (direction != Field::o && direction != Field::m)
        throw InvalidArgument("direction", std::string(field_name(direction)), "o or m");
}

} // namespace ggxcl::detail
