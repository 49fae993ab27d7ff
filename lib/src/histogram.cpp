// histogram.cpp - Sampler::histogram: device-side binning of sample
// directions in launches of bounded size, 32-bit counts per launch summed
// into 64-bit counts on the host.
#include <algorithm>
#include <numeric>

#include "cl_call.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/sampler.hpp"
#include "kernel_launch.hpp"

namespace ggxcl {

namespace {

constexpr std::uint32_t samples_per_item = 64;
constexpr std::uint64_t samples_per_launch = 1u << 30;  // keeps every 32-bit bin count below 2^32

std::string histogram_options(const SampleParams& params, int bins_z, int bins_phi, Field direction)
{
    return detail::build_options(params, 0, {}) + " -DGGX_BINS_Z=" + std::to_string(bins_z) +
           " -DGGX_BINS_PHI=" + std::to_string(bins_phi) + " -DGGX_BIN_M=" + (direction == Field::m ? "1" : "0");
}

void check_bins(int bins_z, int bins_phi, Field direction, std::size_t local_bytes)
{
    std::size_t most = local_bytes / sizeof(cl_uint) - 1;
    if (bins_z < 1 || bins_phi < 1 || std::size_t(bins_z) * bins_phi > most)
        throw InvalidArgument("bins", std::to_string(bins_z) + "x" + std::to_string(bins_phi),
                              "at least 1x1 and at most " + std::to_string(most) +
                                  " bins in all (the device's local memory)");
    if (direction != Field::o && direction != Field::m)
        throw InvalidArgument("direction", std::string(field_name(direction)), "o or m");
}

} // namespace

std::uint64_t Histogram::total() const
{
    return std::accumulate(counts.begin(), counts.end(), non_finite);
}

Histogram Sampler::histogram(const SampleParams& params, const SampleRange& range, int bins_z, int bins_phi,
                             Field direction)
{
    validate(params);
    validate(range);
    SampleParams unit = normalized(params);
    return detail::translate_cl_errors([&] {
        check_bins(bins_z, bins_phi, direction, device_.getInfo<CL_DEVICE_LOCAL_MEM_SIZE>());
        const std::size_t bins = std::size_t(bins_z) * bins_phi;
        Histogram result{bins_z, bins_phi, std::vector<std::uint64_t>(bins, 0), 0};
        KernelLease lease = kernel("ggx_histogram.cl", "ggx_histogram", histogram_options(unit, bins_z, bins_phi, direction));
        cl::Kernel& k = *lease;
        cl::Buffer counts = detail::device_buffer(context_, CL_MEM_READ_WRITE, (bins + 1) * sizeof(cl_uint));
        std::vector<cl_uint> launch_counts(bins + 1);
        const std::vector<cl_uint> zeros(bins + 1, 0u);
        const std::size_t group = work_group_size();
        for (std::uint64_t start = 0; start < range.count; start += samples_per_launch) {
            std::uint64_t n = std::min(samples_per_launch, range.count - start);
            // Zeroed by a write, not clEnqueueFillBuffer: Oclgrind's checker takes
            // filled memory as uninitialized (shown by a minimal kernel in test_oclgrind).
            queue_.enqueueWriteBuffer(counts, CL_FALSE, 0, (bins + 1) * sizeof(cl_uint), zeros.data());
            k.setArg(0, cl_ulong(range.seed));
            k.setArg(1, cl_ulong(range.first + start));
            k.setArg(2, cl_uint(n));
            k.setArg(3, cl_uint(samples_per_item));
            detail::set_param_args(k, 4, unit, {});
            k.setArg(15, counts);
            std::size_t groups = (n + group * samples_per_item - 1) / (group * samples_per_item);
            detail::before_launch();
            queue_.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(groups * group), cl::NDRange(group));
            queue_.enqueueReadBuffer(counts, CL_TRUE, 0, (bins + 1) * sizeof(cl_uint), launch_counts.data());
            for (std::size_t b = 0; b < bins; ++b)
                result.counts[b] += launch_counts[b];
            result.non_finite += launch_counts[bins];
        }
        return result;
    });
}

} // namespace ggxcl
