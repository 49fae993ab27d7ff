// sampler_furnace.cpp - Sampler::furnace and enqueue_furnace: the fused
// white-furnace estimator, which sums the estimator weights per work-item
// on the device (kernels/ggx_furnace.cl) and adds those partial sums in
// double on the host.  Both validate once; their launches go through
// launch_furnace.  furnace() draws each launch without the guards first and
// again with them only when a partial sum is not finite.
#include <algorithm>
#include <cmath>

#include "cl_call.hpp"
#include "device_faults.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/sampler.hpp"
#include "device_contract.hpp"
#include "furnace_sums.hpp"
#include "kernel_launch.hpp"
#include "queue_waits.hpp"
#include "validated_params.hpp"

namespace ggxcl {

namespace {

constexpr std::uint64_t samples_per_launch = 1u << 26;  // a multiple of samples_per_item
constexpr std::uint64_t samples_per_item = detail::furnace_per_item;

// The program of the estimator: it sums weights (its kernel ignores the write mask).
detail::ProgramVariant furnace_variant(const SampleParams& params, const DeviceInputs& inputs)
{
    return detail::variant_of(detail::ProgramKind::furnace, params, detail::write_mask({Field::weight}), inputs);
}

} // namespace

std::size_t Sampler::furnace_items(std::uint64_t count) const
{
    std::size_t group = work_group_size();
    std::uint64_t items = (count + samples_per_item - 1) / samples_per_item;
    return std::size_t((items + group - 1) / group * group);
}

cl::Event Sampler::enqueue_furnace(cl::CommandQueue& queue, const SampleParams& params, const SampleRange& range,
                                   const DeviceArray& sums, const DeviceInputs& inputs,
                                   const std::vector<cl::Event>* wait)
{
    const detail::ValidatedParams valid = detail::validated(params);
    validate(range);
    detail::check_launch_count(range.count, 0);
    if (range.count > (1ull << 31))  // keeps the kernel's 32-bit sample indices from wrapping
        throw InvalidArgument("count", std::to_string(range.count), "1 .. 2^31 per enqueue_furnace");
    return detail::translate_cl_errors([&] {
        detail::check_buffer_sizes(nullptr, inputs, *valid, range.count);
        detail::check_buffer_size(sums, "sums", int(detail::furnace_sum_planes(params)), furnace_items(range.count));
        return launch_furnace(queue, furnace_variant(*valid, inputs), valid, range, sums, inputs, wait);
    });
}

cl::Event Sampler::launch_furnace(cl::CommandQueue& queue, const detail::ProgramVariant& variant,
                                  const detail::ValidatedParams& params, const SampleRange& range,
                                  const DeviceArray& sums, const DeviceInputs& inputs,
                                  const std::vector<cl::Event>* wait)
{
    KernelLease lease = kernel(detail::program_file(detail::ProgramKind::furnace), "ggx_furnace_bulk",
                               detail::build_options(device_, variant));
    cl::Kernel& k = *lease;
    k.setArg(detail::arg_seed, cl_ulong(range.seed));
    k.setArg(detail::arg_first, cl_ulong(range.first));
    k.setArg(detail::arg_count, cl_uint(range.count));
    k.setArg(detail::arg_stride, cl_uint(range.count));
    detail::set_param_args(k, detail::arg_params, *params, inputs);
    k.setArg(detail::arg_outputs, sums.buffer);
    k.setArg(detail::arg_sums_offset, cl_ulong(sums.offset));
    cl::Event event;
    detail::before_launch();
    queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(furnace_items(range.count)),
                               cl::NDRange(work_group_size()), wait, &event);
    return event;
}

// Adds the sums of one launch to `total`: unguarded first, and again with
// guards if a partial sum is not finite.
void Sampler::add_furnace_launch(const detail::ValidatedParams& params, const SampleRange& range,
                                 const cl::Buffer& sums, std::vector<float>& host, FurnaceSums& total)
{
    const std::size_t used = furnace_items(range.count), planes = detail::furnace_sum_planes(*params);
    SampleParams unguarded = *params, guarded = *params;
    unguarded.guards = false;
    guarded.guards = true;
    for (const detail::ProgramVariant& variant : {furnace_variant(unguarded, {}), furnace_variant(guarded, {})}) {
        launch_furnace(queue_, variant, params, range, sums, {}, nullptr);
        detail::read_and_wait(queue_, sums, 0, planes * used * sizeof(float), host.data());
        // One order of additions, whatever the launches; the guarded pass counts even if not finite.
        if (detail::add_furnace_partial_sums(host.data(), used, planes, total, variant.guards) || variant.guards)
            return;
    }
}

FurnaceSums Sampler::furnace(const SampleParams& params, const SampleRange& range)
{
    const detail::ValidatedParams valid = detail::validated(params);
    validate(range);
    FurnaceSums total;
    total.count = range.count;
    detail::translate_cl_errors([&] {
        std::uint64_t start = 0, launch_size = std::min(samples_per_launch, range.count);
        auto run_launches = [&](std::uint64_t per_launch) {
            std::size_t floats = detail::furnace_sum_planes(*valid) * furnace_items(per_launch);
            cl::Buffer sums = detail::device_buffer(context_, CL_MEM_WRITE_ONLY, floats * sizeof(float));
            std::vector<float> host(floats);
            for (; start < range.count; start += per_launch) {  // start: the first sample not summed
                std::uint64_t n = std::min(per_launch, range.count - start);
                add_furnace_launch(valid, {range.seed, range.first + start, n}, sums, host, total);
            }
        };  // launches start at multiples of samples_per_item: the same partial sums however split
        detail::retry_with_smaller_chunks(launch_size, 1024, memory_retries_, run_launches, samples_per_item);
        return 0;
    });
    return total;
}

} // namespace ggxcl
