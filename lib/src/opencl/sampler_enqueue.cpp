// sampler_enqueue.cpp - the Sampler's construction and settings, and its
// launches into the caller's buffers at their offsets: enqueue, warm_up,
// enqueue_pdf and enqueue_eval, each validating its arguments once and then
// launching through launch_samples or launch_directions, which the
// host-memory front ends (sampler_generate.cpp) call per chunk.  The
// histogram and the fused estimator are in sampler_histogram.cpp and
// sampler_furnace.cpp.
#include "ggxcl/sampler.hpp"

#include <algorithm>
#include <iterator>
#include <limits>

#include "cl_call.hpp"
#include "device_contract.hpp"
#include "kernel_launch.hpp"
#include "validated_params.hpp"
#include "ggxcl/error.hpp"

namespace ggxcl {

namespace {

using detail::translate_cl_errors;

const char* const bulk_file = detail::program_file(detail::ProgramKind::bulk);

unsigned write_mask_of(const DeviceOutputs& out)
{
    FieldSet given;
    for (Field f : all_fields)
        if (out.of(f)() != nullptr)
            given.add(f);
    return detail::write_mask(given);
}

} // namespace

using namespace detail;

cl::Buffer& DeviceOutputs::of(Field field)
{
    cl::Buffer* buffers[] = {&m, &o, &pdf_m, &pdf_o, &weight, &u};
    static_assert(std::size(buffers) == all_fields.size());
    return *buffers[static_cast<int>(field)];
}

const cl::Buffer& DeviceOutputs::of(Field field) const
{
    return const_cast<DeviceOutputs*>(this)->of(field);
}

std::uint64_t& DeviceOutputs::offset_of(Field field)
{
    std::uint64_t* offsets[] = {&m_offset, &o_offset, &pdf_m_offset, &pdf_o_offset, &weight_offset, &u_offset};
    static_assert(std::size(offsets) == all_fields.size());
    return *offsets[static_cast<int>(field)];
}

std::uint64_t DeviceOutputs::offset_of(Field field) const
{
    return const_cast<DeviceOutputs*>(this)->offset_of(field);
}

Sampler::Sampler(const std::string& selector) : Sampler(select_device(selector)) {}

Sampler::Sampler(const DeviceInfo& device) : Sampler(translate_cl_errors([&] { return cl::Context(device.device); }), device.device) {}

Sampler::Sampler(const cl::Context& context, const cl::Device& device)
    : context_(context), device_(device), programs_(ProgramCache::for_context(context))
{
    translate_cl_errors([&] {
        queue_ = cl::CommandQueue(context_, device_, CL_QUEUE_PROFILING_ENABLE);
        device_max_group_ = device_.getInfo<CL_DEVICE_MAX_WORK_GROUP_SIZE>();
        max_alloc_ = device_.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
        local_mem_ = device_.getInfo<CL_DEVICE_LOCAL_MEM_SIZE>();
        compute_units_ = device_.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
        cpu_ = (device_.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) != 0;
        host_unified_ = device_.getInfo<CL_DEVICE_HOST_UNIFIED_MEMORY>() == CL_TRUE;
        return 0;
    });
}

std::string Sampler::device_name() const
{
    return translate_cl_errors([&] { return device_.getInfo<CL_DEVICE_NAME>(); });
}

void Sampler::set_chunk_size(std::uint64_t samples)
{
    if (samples == 0 || samples > (1ull << 30))
        throw InvalidArgument("chunk size", std::to_string(samples), "1 .. 2^30 samples");
    chunk_size_ = samples;
}

void Sampler::set_work_group_size(std::size_t items)
{
    if (items > device_max_group_)
        throw InvalidArgument("work-group size", std::to_string(items),
                              "0 (automatic) or 1 .. " + std::to_string(device_max_group_) + " (the device's maximum)");
    work_group_size_ = items;
}

std::size_t Sampler::work_group_size() const
{
    return group_size(device_max_group_, work_group_size_);
}

std::size_t Sampler::programs_built() const
{
    return programs_->size();
}

std::size_t Sampler::programs_from_disk() const
{
    return programs_->loaded_from_disk();
}

KernelLease Sampler::kernel(const std::string& file, const std::string& name, const std::string& options)
{
    return programs_->kernel(device_, file, options, name);
}

cl::Event Sampler::enqueue(cl::CommandQueue& queue, const SampleParams& params, const SampleRange& range,
                           const DeviceOutputs& outputs, std::uint32_t stride, const DeviceInputs& inputs,
                           const std::vector<cl::Event>* wait)
{
    const ValidatedParams valid = validated(params);
    validate(range);
    check_launch_count(range.count, stride);
    if (write_mask_of(outputs) == 0)
        throw InvalidArgument("outputs", "none", "at least one output buffer (" + field_list() + ")");
    return translate_cl_errors([&] {
        check_buffer_sizes(&outputs, inputs, *valid, stride ? stride : range.count);
        const ProgramVariant variant = variant_of(ProgramKind::bulk, *valid, write_mask_of(outputs), inputs);
        return launch_samples(queue, variant, valid, range, outputs, stride, inputs, wait);
    });
}

cl::Event Sampler::launch_samples(cl::CommandQueue& queue, const ProgramVariant& variant, const ValidatedParams& params,
                                  const SampleRange& range, const DeviceOutputs& outputs, std::uint32_t stride,
                                  const DeviceInputs& inputs, const std::vector<cl::Event>* wait)
{
    const std::string options = build_options(device_, variant);
    auto make = [&](const std::string& name) {
        KernelLease lease = kernel(bulk_file, name, options);
        cl::Kernel& k = *lease;
        k.setArg(arg_seed, cl_ulong(range.seed));
        k.setArg(arg_first, cl_ulong(range.first));
        k.setArg(arg_count, cl_uint(range.count));
        k.setArg(arg_stride, cl_uint(stride ? stride : range.count));
        set_param_args(k, arg_params, *params, inputs);
        for (Field f : all_fields) {
            k.setArg(arg_output(f), outputs.of(f));
            k.setArg(arg_output_offset(f), cl_ulong(outputs.offset_of(f)));
        }
        return lease;
    };
    return launch_split(queue, work_group_size(), make, "ggx_sample_bulk", cl_uint(range.count), wait);
}

void Sampler::warm_up(const SampleParams& params, FieldSet fields, const DeviceInputs& inputs)
{
    if (fields.empty())
        throw InvalidArgument("fields", "none", "at least one field to warm up (" + field_list() + ")");
    const ValidatedParams valid = validated(params);
    // One whole work-group and a tail: both kernels of launch_split.
    const std::uint32_t count = std::uint32_t(work_group_size() + 1);
    translate_cl_errors([&] {
        auto floats = [&](std::size_t planes, const float* fill) {
            std::vector<float> values(planes * count);
            for (std::size_t j = 0; j < values.size(); ++j)
                values[j] = fill[j / count];
            return cl::Buffer(context_, values.begin(), values.end(), false);
        };
        const float unit_z[] = {0.0f, 0.0f, 1.0f}, half[] = {0.5f, 0.5f, 0.5f}, zero[] = {0.0f, 0.0f, 0.0f};
        const bool dielectric = (*valid).eta != 0.0f;
        DeviceInputs scratch_inputs = inputs;  // the same kinds of inputs, at offset 0
        scratch_inputs.view_offset = scratch_inputs.alpha_offset = scratch_inputs.normal_offset =
            scratch_inputs.uniforms_offset = 0;
        if (inputs.view() != nullptr) scratch_inputs.view = floats(3, unit_z);
        if (inputs.alpha() != nullptr) scratch_inputs.alpha = floats(2, half);
        if (inputs.normal() != nullptr) scratch_inputs.normal = floats(3, unit_z);
        if (inputs.uniforms() != nullptr) scratch_inputs.uniforms = floats(dielectric ? 3 : 2, half);
        DeviceOutputs outputs;
        for (Field f : all_fields)
            if (fields.has(f))
                outputs.of(f) = floats(field_columns(f, dielectric), zero);
        const ProgramVariant variant = variant_of(ProgramKind::bulk, *valid, write_mask(fields), scratch_inputs);
        launch_samples(queue_, variant, valid, {0, 0, count}, outputs, 0, scratch_inputs, nullptr).wait();
        return 0;
    });
}

namespace {

// enqueue_pdf and enqueue_eval: the arguments checked, then the pdf kernels of the request's variant,
// computing the pdf or (eval) the BSDF value.
template <class Launch>
cl::Event checked_directions(const SampleParams& params, std::uint32_t count, const DeviceArray& directions,
                             const DeviceArray& out, const char* out_name, std::uint32_t stride,
                             const DeviceInputs& inputs, bool eval, Launch&& launch)
{
    const ValidatedParams valid = validated(params);
    check_launch_count(count, stride);
    return translate_cl_errors([&] {
        const std::uint64_t planes_stride = stride ? stride : count;
        check_buffer_sizes(nullptr, inputs, *valid, planes_stride);
        check_buffer_size(directions, "directions", 3, planes_stride);
        check_buffer_size(out, out_name, 1, planes_stride);
        ProgramVariant variant = variant_of(ProgramKind::bulk, *valid, 0, inputs);
        variant.eval = eval;
        return launch(variant, valid);
    });
}

} // namespace

cl::Event Sampler::enqueue_pdf(cl::CommandQueue& queue, const SampleParams& params, std::uint32_t count,
                               const DeviceArray& directions, const DeviceArray& pdf_out, std::uint32_t stride,
                               const DeviceInputs& inputs, const std::vector<cl::Event>* wait)
{
    return checked_directions(params, count, directions, pdf_out, "pdf_out", stride, inputs, false,
                              [&](const ProgramVariant& variant, const ValidatedParams& valid) {
                                  return launch_directions(queue, variant, valid, count, directions, pdf_out, stride,
                                                           inputs, wait);
                              });
}

cl::Event Sampler::enqueue_eval(cl::CommandQueue& queue, const SampleParams& params, std::uint32_t count,
                                const DeviceArray& directions, const DeviceArray& values, std::uint32_t stride,
                                const DeviceInputs& inputs, const std::vector<cl::Event>* wait)
{
    return checked_directions(params, count, directions, values, "values", stride, inputs, true,
                              [&](const ProgramVariant& variant, const ValidatedParams& valid) {
                                  return launch_directions(queue, variant, valid, count, directions, values, stride,
                                                           inputs, wait);
                              });
}

cl::Event Sampler::launch_directions(cl::CommandQueue& queue, const ProgramVariant& variant,
                                     const ValidatedParams& params, std::uint32_t count, const DeviceArray& directions,
                                     const DeviceArray& out, std::uint32_t stride, const DeviceInputs& inputs,
                                     const std::vector<cl::Event>* wait)
{
    const std::string options = build_options(device_, variant);
    auto make = [&](const std::string& name) {
        KernelLease lease = kernel(bulk_file, name, options);
        cl::Kernel& k = *lease;
        k.setArg(pdf_arg_count, cl_uint(count));
        k.setArg(pdf_arg_stride, cl_uint(stride ? stride : count));
        set_param_args(k, pdf_arg_params, *params, inputs);
        k.setArg(pdf_arg_directions, directions.buffer);
        k.setArg(pdf_arg_pdfs, out.buffer);
        k.setArg(pdf_arg_directions_offset, cl_ulong(directions.offset));
        k.setArg(pdf_arg_pdfs_offset, cl_ulong(out.offset));
        return lease;
    };
    return launch_split(queue, work_group_size(), make, "ggx_pdf_bulk", count, wait);
}

} // namespace ggxcl
