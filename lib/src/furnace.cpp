// furnace.cpp - Sampler::furnace and enqueue_furnace: the fused
// white-furnace estimator, which sums the estimator weights per work-item
// on the device (kernels/ggx_furnace.cl) and adds those partial sums in
// double on the host.
#include <algorithm>
#include <cmath>

#include "cl_call.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/sampler.hpp"
#include "kernel_launch.hpp"

namespace ggxcl {

namespace {

constexpr std::uint64_t samples_per_launch = 1u << 26;
constexpr std::uint64_t samples_per_item = 8;  // GGX_FURNACE_PER_ITEM of ggx_furnace.cl

// The partial sums of one launch added in double; false if one of them is not finite.
bool add_partial_sums(const std::vector<float>& host, std::size_t items, double& sum, double& sum_of_squares)
{
    for (std::size_t g = 0; g < items; ++g) {
        if (!std::isfinite(host[g]) || !std::isfinite(host[items + g]))
            return false;
        sum += host[g];
        sum_of_squares += host[items + g];
    }
    return true;
}

} // namespace

double FurnaceSums::mean() const
{
    return count ? sum / double(count) : 0.0;
}

double FurnaceSums::variance() const
{
    if (count < 2)
        return 0.0;
    double m = mean();
    return std::max(0.0, (sum_of_squares - double(count) * m * m) / double(count - 1));
}

std::size_t Sampler::furnace_items(std::uint64_t count) const
{
    std::size_t group = detail::group_size(device_);
    std::uint64_t items = (count + samples_per_item - 1) / samples_per_item;
    return std::size_t((items + group - 1) / group * group);
}

cl::Event Sampler::enqueue_furnace(cl::CommandQueue& queue, const SampleParams& params, const SampleRange& range,
                                   const cl::Buffer& sums, const DeviceInputs& inputs,
                                   const std::vector<cl::Event>* wait)
{
    validate(params);
    validate(range);
    detail::check_launch_count(range.count, 0);
    SampleParams unit = normalized(params);
    return detail::translate_cl_errors([&] {
        cl::Kernel k = kernel("ggx_furnace.cl", "ggx_furnace_bulk", detail::build_options(unit, 16u, inputs));
        k.setArg(0, cl_ulong(range.seed));
        k.setArg(1, cl_ulong(range.first));
        k.setArg(2, cl_uint(range.count));
        k.setArg(3, cl_uint(range.count));
        detail::set_param_args(k, 4, unit, inputs);
        k.setArg(15, sums);
        cl::Event event;
        queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(furnace_items(range.count)),
                                   cl::NDRange(detail::group_size(device_)), wait, &event);
        return event;
    });
}

FurnaceSums Sampler::furnace(const SampleParams& params, const SampleRange& range)
{
    validate(params);
    validate(range);
    FurnaceSums total;
    total.count = range.count;
    const std::uint64_t per_launch = std::min(samples_per_launch, range.count);
    detail::translate_cl_errors([&] {
        cl::Buffer sums(context_, CL_MEM_WRITE_ONLY, 2 * furnace_items(per_launch) * sizeof(float));
        std::vector<float> host(2 * furnace_items(per_launch));
        for (std::uint64_t start = 0; start < range.count; start += per_launch) {
            std::uint64_t n = std::min(per_launch, range.count - start);
            std::size_t used = furnace_items(n);
            SampleParams attempt = params;
            for (bool guarded : {false, true}) {  // unguarded first; a non-finite sum reruns with guards
                attempt.guards = guarded;
                enqueue_furnace(queue_, attempt, {range.seed, range.first + start, n}, sums);
                queue_.enqueueReadBuffer(sums, CL_TRUE, 0, 2 * used * sizeof(float), host.data());
                double sum = 0.0, sum_of_squares = 0.0;
                if (add_partial_sums(host, used, sum, sum_of_squares) || guarded) {
                    total.sum += sum;
                    total.sum_of_squares += sum_of_squares;
                    break;
                }
            }
        }
        return 0;
    });
    return total;
}

} // namespace ggxcl
