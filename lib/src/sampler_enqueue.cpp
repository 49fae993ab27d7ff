// sampler_enqueue.cpp - the Sampler's construction and settings, and its
// launches into the caller's buffers: enqueue, warm_up, enqueue_pdf, each
// validating its arguments once and then launching through
// enqueue_validated or enqueue_pdf_validated, which the host-memory front
// ends (sampler_generate.cpp) call per chunk.  The histogram and the fused
// estimator are in sampler_histogram.cpp and sampler_furnace.cpp.
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

std::vector<float>& SampleSet::column_source(Field field)
{
    std::vector<float>* planes[] = {&m, &o, &pdf_m, &pdf_o, &weight, &u};
    static_assert(std::size(planes) == all_fields.size());
    return *planes[static_cast<int>(field)];
}

const std::vector<float>& SampleSet::column_source(Field field) const
{
    return const_cast<SampleSet*>(this)->column_source(field);
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
    return enqueue_variant(queue, params, range, outputs, stride, inputs, wait, true);
}

cl::Event Sampler::enqueue_variant(cl::CommandQueue& queue, const SampleParams& params, const SampleRange& range,
                                   const DeviceOutputs& outputs, std::uint32_t stride, const DeviceInputs& inputs,
                                   const std::vector<cl::Event>* wait, bool guards)
{
    const ValidatedParams valid = validated(params);
    validate(range);
    check_launch_count(range.count, stride);
    if (write_mask_of(outputs) == 0)
        throw InvalidArgument("outputs", "none", "at least one output buffer (" + field_list() + ")");
    return translate_cl_errors([&] {
        check_buffer_sizes(&outputs, inputs, *valid, stride ? stride : range.count);
        return enqueue_validated(queue, valid, range, outputs, stride, inputs, wait, guards);
    });
}

cl::Event Sampler::enqueue_validated(cl::CommandQueue& queue, const ValidatedParams& params, const SampleRange& range,
                                     const DeviceOutputs& outputs, std::uint32_t stride, const DeviceInputs& inputs,
                                     const std::vector<cl::Event>* wait, bool guards)
{
    std::string options = build_options(device_, *params, write_mask_of(outputs), inputs, guards);
    auto make = [&](const std::string& name) {
        KernelLease lease = kernel(bulk_file, name, options);
        cl::Kernel& k = *lease;
        k.setArg(arg_seed, cl_ulong(range.seed));
        k.setArg(arg_first, cl_ulong(range.first));
        k.setArg(arg_count, cl_uint(range.count));
        k.setArg(arg_stride, cl_uint(stride ? stride : range.count));
        set_param_args(k, arg_params, *params, inputs);
        for (Field f : all_fields)
            k.setArg(arg_output(f), outputs.of(f));
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
        DeviceInputs scratch_inputs = inputs;
        if (inputs.view() != nullptr) scratch_inputs.view = floats(3, unit_z);
        if (inputs.alpha() != nullptr) scratch_inputs.alpha = floats(2, half);
        if (inputs.normal() != nullptr) scratch_inputs.normal = floats(3, unit_z);
        if (inputs.uniforms() != nullptr) scratch_inputs.uniforms = floats(dielectric ? 3 : 2, half);
        DeviceOutputs outputs;
        for (Field f : all_fields)
            if (fields.has(f))
                outputs.of(f) = floats(field_columns(f, dielectric), zero);
        enqueue_validated(queue_, valid, {0, 0, count}, outputs, 0, scratch_inputs, nullptr, true).wait();
        return 0;
    });
}

cl::Event Sampler::enqueue_pdf(cl::CommandQueue& queue, const SampleParams& params, std::uint32_t count,
                               const cl::Buffer& directions, const cl::Buffer& pdf_out, std::uint32_t stride,
                               const DeviceInputs& inputs, const std::vector<cl::Event>* wait)
{
    return enqueue_directions(queue, params, count, directions, pdf_out, stride, inputs, wait, false);
}

cl::Event Sampler::enqueue_eval(cl::CommandQueue& queue, const SampleParams& params, std::uint32_t count,
                                const cl::Buffer& directions, const cl::Buffer& values, std::uint32_t stride,
                                const DeviceInputs& inputs, const std::vector<cl::Event>* wait)
{
    return enqueue_directions(queue, params, count, directions, values, stride, inputs, wait, true);
}

cl::Event Sampler::enqueue_directions(cl::CommandQueue& queue, const SampleParams& params, std::uint32_t count,
                                      const cl::Buffer& directions, const cl::Buffer& out, std::uint32_t stride,
                                      const DeviceInputs& inputs, const std::vector<cl::Event>* wait, bool eval)
{
    const ValidatedParams valid = validated(params);
    check_launch_count(count, stride);
    return translate_cl_errors([&] {
        const std::uint64_t planes_stride = stride ? stride : count;
        check_buffer_sizes(nullptr, inputs, *valid, planes_stride);
        check_buffer_size(directions, "directions", 3, planes_stride);
        check_buffer_size(out, eval ? "values" : "pdf_out", 1, planes_stride);
        return enqueue_pdf_validated(queue, valid, count, directions, out, stride, inputs, wait, eval);
    });
}

cl::Event Sampler::enqueue_pdf_validated(cl::CommandQueue& queue, const ValidatedParams& params, std::uint32_t count,
                                         const cl::Buffer& directions, const cl::Buffer& pdf_out, std::uint32_t stride,
                                         const DeviceInputs& inputs, const std::vector<cl::Event>* wait, bool eval)
{
    ProgramVariant variant = variant_of(ProgramKind::bulk, *params, 0, inputs, true);
    variant.eval = eval;
    const std::string options = build_options(device_, variant);
    auto make = [&](const std::string& name) {
        KernelLease lease = kernel(bulk_file, name, options);
        cl::Kernel& k = *lease;
        k.setArg(pdf_arg_count, cl_uint(count));
        k.setArg(pdf_arg_stride, cl_uint(stride ? stride : count));
        set_param_args(k, pdf_arg_params, *params, inputs);
        k.setArg(pdf_arg_directions, directions);
        k.setArg(pdf_arg_pdfs, pdf_out);
        return lease;
    };
    return launch_split(queue, work_group_size(), make, "ggx_pdf_bulk", count, wait);
}

} // namespace ggxcl
