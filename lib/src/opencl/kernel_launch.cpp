// kernel_launch.cpp - build options, parameter arguments and launches
// shared by the Sampler's kernels.
#include "kernel_launch.hpp"

#include <algorithm>
#include <iterator>
#include <limits>

#include "device_contract.hpp"
#include "device_faults.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/user_kernels.hpp"

namespace ggxcl {

namespace detail {

bool is_isotropic(const SampleParams& params, const DeviceInputs& inputs)
{
    if (method_traits(params.method).isotropic_only || params.world_space)
        return true;  // validated isotropic
    return inputs.alpha() != nullptr ? inputs.isotropic : params.alpha_x == params.alpha_y;
}

bool is_above_horizon(const SampleParams& params, const DeviceInputs& inputs)
{
    bool against_normal = uses_normal(params);
    if (inputs.view() != nullptr || (against_normal && inputs.normal() != nullptr))
        return inputs.views_above_horizon;
    return view_above_horizon(params.view, params.normal, against_normal);
}

ProgramVariant variant_of(ProgramKind kind, const SampleParams& params, unsigned write_mask,
                          const DeviceInputs& inputs)
{
    PerSampleKinds kinds;
    kinds.view = inputs.view() != nullptr;
    kinds.alpha = inputs.alpha() != nullptr;
    kinds.normal = inputs.normal() != nullptr;
    kinds.uniforms = inputs.uniforms() != nullptr;
    kinds.isotropic = is_isotropic(params, inputs);
    kinds.above_horizon = is_above_horizon(params, inputs);
    return variant_of(kind, params, write_mask, kinds);
}

std::string build_options(const cl::Device& device, const ProgramVariant& variant)
{
    return variant_defines(variant) + precision_options(device, variant.precision);
}

void set_param_args(cl::Kernel& kernel, cl_uint first_arg, const SampleParams& p, const DeviceInputs& in)
{
    const float values[GGX_PARAM_UNIFORM_COUNT] = {p.view.x,   p.view.y,   p.view.z,   p.alpha_x, p.alpha_y,
                                                   p.normal.x, p.normal.y, p.normal.z, p.eta};
    for (cl_uint k = 0; k < GGX_PARAM_UNIFORM_COUNT; ++k)
        kernel.setArg(first_arg + k, values[k]);
    const cl::Buffer* buffers[] = {&in.view, &in.alpha, &in.normal, &in.uniforms};
    const std::uint64_t offsets[] = {in.view_offset, in.alpha_offset, in.normal_offset, in.uniforms_offset};
    static_assert(std::size(buffers) == GGX_PARAM_BUFFER_COUNT);
    for (cl_uint k = 0; k < std::size(buffers); ++k) {
        kernel.setArg(first_arg + GGX_PARAM_UNIFORM_COUNT + k, *buffers[k]);
        kernel.setArg(first_arg + GGX_PARAM_UNIFORM_COUNT + GGX_PARAM_BUFFER_COUNT + k, cl_ulong(offsets[k]));
    }
}

void check_launch_count(std::uint64_t count, std::uint32_t stride)
{
    if (count == 0 || count > std::numeric_limits<std::uint32_t>::max() - preferred_group_size)
        throw InvalidArgument("count", std::to_string(count), "1 .. 2^32 - 257 per enqueue");
    if (stride != 0 && stride < count)
        throw InvalidArgument("stride", std::to_string(stride), "0 (= count) or at least count");
}

void check_buffer_size(const DeviceArray& array, const std::string& name, int planes, std::uint64_t stride)
{
    if (array.buffer() == nullptr)
        return;
    const std::uint64_t floats = array.buffer.getInfo<CL_MEM_SIZE>() / sizeof(float);
    const std::uint64_t needed = std::uint64_t(planes) * stride;
    if (array.offset > floats || floats - array.offset < needed)
        throw InvalidArgument(name, "a buffer of " + std::to_string(floats) + " floats with offset " +
                                        std::to_string(array.offset),
                              "offset + " + std::to_string(needed) + " floats (" + std::to_string(planes) +
                                  (planes == 1 ? " plane" : " planes") + " of stride " + std::to_string(stride) +
                                  ") within the buffer");
}

void check_buffer_sizes(const DeviceOutputs* outputs, const DeviceInputs& inputs, const SampleParams& params,
                        std::uint64_t stride)
{
    const bool dielectric = params.eta != 0.0f;
    if (outputs)
        for (Field f : all_fields)
            check_buffer_size({outputs->of(f), outputs->offset_of(f)}, "outputs." + std::string(field_name(f)),
                              field_columns(f, dielectric), stride);
    check_buffer_size({inputs.view, inputs.view_offset}, "inputs.view", 3, stride);
    check_buffer_size({inputs.alpha, inputs.alpha_offset}, "inputs.alpha", is_isotropic(params, inputs) ? 1 : 2,
                      stride);
    check_buffer_size({inputs.normal, inputs.normal_offset}, "inputs.normal", 3, stride);
    check_buffer_size({inputs.uniforms, inputs.uniforms_offset}, "inputs.uniforms", dielectric ? 3 : 2, stride);
}

std::size_t group_size(std::size_t device_max, std::size_t requested)
{
    return requested ? requested : std::min(preferred_group_size, device_max);
}

cl::Event launch_split(cl::CommandQueue& queue, std::size_t group, const KernelMaker& make,
                       const std::string& name, std::uint32_t count, const std::vector<cl::Event>* wait)
{
    before_launch();
    std::size_t full = count / group * group;
    std::vector<cl::Event> launched;
    if (full > 0) {
        launched.emplace_back();
        KernelLease whole = make(name);
        queue.enqueueNDRangeKernel(*whole, cl::NullRange, cl::NDRange(full), cl::NDRange(group), wait, &launched.back());
    }
    if (full < count) {
        launched.emplace_back();
        KernelLease tail = make(name + "_tail");
        queue.enqueueNDRangeKernel(*tail, cl::NDRange(full), cl::NDRange(group), cl::NDRange(group), wait,
                                   &launched.back());
    }
    if (launched.size() == 1)
        return launched.front();
    cl::Event both;  // one event for both launches, also on an out-of-order queue
    queue.enqueueMarkerWithWaitList(&launched, &both);
    return both;
}

} // namespace detail

} // namespace ggxcl
