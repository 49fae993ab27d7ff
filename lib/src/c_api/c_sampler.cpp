// c_sampler.cpp - the C API's samplers and user samplers, and the enqueue
// calls into the caller's buffers on the caller's queue.
#include <string>

#include "c_api/c_buffers.hpp"
#include "c_api/c_handles.hpp"
#include "c_api/c_params.hpp"
#include "c_api/c_status.hpp"
#include "ggxcl/error.hpp"

using namespace ggxcl::capi;
using ggxcl::DeviceInputs;
using ggxcl::Field;
using ggxcl::SampleParams;

namespace {

// The caller's per-sample inputs of `count` samples, placed for a call (u has 3 planes for a dielectric).
DeviceInputs place_inputs(PlacedBuffers& placed, const ggxcl_device_inputs* inputs, const SampleParams& params,
                          std::uint64_t count, std::uint64_t stride)
{
    DeviceInputs in;
    if (!inputs)
        return in;
    in.view = placed.input(inputs->view, "inputs.view", 3, count, stride);
    in.alpha = placed.input(inputs->alpha, "inputs.alpha", 2, count, stride);
    in.normal = placed.input(inputs->normal, "inputs.normal", 3, count, stride);
    in.uniforms = placed.input(inputs->uniforms, "inputs.uniforms", ggxcl::field_columns(Field::u, params.eta != 0.0f),
                               count, stride);
    in.views_above_horizon = inputs->views_above_horizon != 0;
    in.isotropic = inputs->isotropic != 0;
    return in;
}

// Runs `launch(queue, kernel_wait)` between the input copies and the output copies of `placed`.
template <class Launch>
void enqueue_placed(cl_command_queue queue, PlacedBuffers& placed, cl_uint wait_count, const cl_event* wait,
                    cl_event* event, Launch&& launch)
{
    cl::CommandQueue caller_queue(non_null(queue, "queue"), true);
    const std::vector<cl::Event> kernel_wait = placed.before_kernel(caller_queue, wait_list(wait_count, wait));
    const cl::Event kernel = launch(caller_queue, kernel_wait);
    hand_over(placed.after_kernel(caller_queue, kernel), event);
}

const std::vector<cl::Event>* or_null(const std::vector<cl::Event>& wait) { return wait.empty() ? nullptr : &wait; }

ggxcl_status enqueue_directions(ggxcl_sampler* sampler, cl_command_queue queue, const ggxcl_params* params,
                                uint32_t count, ggxcl_buffer directions, ggxcl_buffer out, uint32_t stride,
                                const ggxcl_device_inputs* inputs, cl_uint wait_count, const cl_event* wait,
                                cl_event* event, bool eval)
{
    return guarded([&] {
        ggxcl::Sampler& s = require(sampler, "sampler").sampler;
        const SampleParams p = to_params(params);
        PlacedBuffers placed(s.context(), sampler->base_align_bytes);
        const cl::Buffer dirs = placed.input(directions, "directions", 3, count, stride);
        const cl::Buffer values = placed.output(out, eval ? "values" : "pdfs", 1, count, stride);
        const DeviceInputs in = place_inputs(placed, inputs, p, count, stride);
        enqueue_placed(queue, placed, wait_count, wait, event, [&](cl::CommandQueue& q, const std::vector<cl::Event>& w) {
            return eval ? s.enqueue_eval(q, p, count, dirs, values, stride, in, or_null(w))
                        : s.enqueue_pdf(q, p, count, dirs, values, stride, in, or_null(w));
        });
    });
}

} // namespace

extern "C" {

ggxcl_status ggxcl_sampler_create(const char* selector, ggxcl_sampler** sampler)
{
    return guarded([&] {
        ggxcl_sampler*& out = require(sampler, "sampler");
        out = nullptr;
        out = new ggxcl_sampler(selector ? selector : "");
    });
}

ggxcl_status ggxcl_sampler_create_with_context(cl_context context, cl_device_id device, ggxcl_sampler** sampler)
{
    return guarded([&] {
        ggxcl_sampler*& out = require(sampler, "sampler");
        out = nullptr;
        out = new ggxcl_sampler(cl::Context(non_null(context, "context"), true), cl::Device(non_null(device, "device"), true));
    });
}

void ggxcl_sampler_release(ggxcl_sampler* sampler) { delete sampler; }

cl_context ggxcl_sampler_context(const ggxcl_sampler* sampler) { return sampler ? sampler->sampler.context()() : nullptr; }
cl_device_id ggxcl_sampler_device(const ggxcl_sampler* sampler) { return sampler ? sampler->sampler.device()() : nullptr; }
cl_command_queue ggxcl_sampler_queue(const ggxcl_sampler* sampler)
{
    return sampler ? const_cast<ggxcl_sampler*>(sampler)->sampler.queue()() : nullptr;
}
const char* ggxcl_sampler_device_name(const ggxcl_sampler* sampler)
{
    return sampler ? sampler->device_name.c_str() : "";
}

ggxcl_status ggxcl_user_sampler_load(const char* path, const char* name, ggxcl_user_sampler** sampler)
{
    return guarded([&] {
        ggxcl_user_sampler*& out = require(sampler, "sampler");
        out = nullptr;
        out = new ggxcl_user_sampler{ggxcl::UserSampler::load(non_null(path, "path"), name ? name : "")};
    });
}

void ggxcl_user_sampler_release(ggxcl_user_sampler* sampler) { delete sampler; }
const char* ggxcl_user_sampler_name(const ggxcl_user_sampler* sampler)
{
    return sampler ? sampler->sampler->name().c_str() : "";
}

ggxcl_status ggxcl_enqueue(ggxcl_sampler* sampler, cl_command_queue queue, const ggxcl_params* params,
                           const ggxcl_range* range, const ggxcl_device_outputs* outputs, uint32_t stride,
                           const ggxcl_device_inputs* inputs, cl_uint wait_count, const cl_event* wait,
                           cl_event* event)
{
    return guarded([&] {
        ggxcl::Sampler& s = require(sampler, "sampler").sampler;
        const SampleParams p = to_params(params);
        const ggxcl::SampleRange r = to_range(range);
        const ggxcl_device_outputs& out = require(outputs, "outputs");
        PlacedBuffers placed(s.context(), sampler->base_align_bytes);
        ggxcl::DeviceOutputs device_out;
        for (Field field : ggxcl::all_fields) {
            const std::string name = "outputs." + std::string(ggxcl::field_name(field));
            device_out.of(field) = placed.output(output_of(out, field), name.c_str(),
                                                 ggxcl::field_columns(field, p.eta != 0.0f), r.count, stride);
        }
        const DeviceInputs in = place_inputs(placed, inputs, p, r.count, stride);
        enqueue_placed(queue, placed, wait_count, wait, event, [&](cl::CommandQueue& q, const std::vector<cl::Event>& w) {
            return s.enqueue(q, p, r, device_out, stride, in, or_null(w));
        });
    });
}

ggxcl_status ggxcl_enqueue_pdf(ggxcl_sampler* sampler, cl_command_queue queue, const ggxcl_params* params,
                               uint32_t count, ggxcl_buffer directions, ggxcl_buffer pdfs, uint32_t stride,
                               const ggxcl_device_inputs* inputs, cl_uint wait_count, const cl_event* wait,
                               cl_event* event)
{
    return enqueue_directions(sampler, queue, params, count, directions, pdfs, stride, inputs, wait_count, wait,
                              event, false);
}

ggxcl_status ggxcl_enqueue_eval(ggxcl_sampler* sampler, cl_command_queue queue, const ggxcl_params* params,
                                uint32_t count, ggxcl_buffer directions, ggxcl_buffer values, uint32_t stride,
                                const ggxcl_device_inputs* inputs, cl_uint wait_count, const cl_event* wait,
                                cl_event* event)
{
    return enqueue_directions(sampler, queue, params, count, directions, values, stride, inputs, wait_count, wait,
                              event, true);
}

ggxcl_status ggxcl_enqueue_furnace(ggxcl_sampler* sampler, cl_command_queue queue, const ggxcl_params* params,
                                   const ggxcl_range* range, ggxcl_buffer sums, const ggxcl_device_inputs* inputs,
                                   cl_uint wait_count, const cl_event* wait, cl_event* event)
{
    return guarded([&] {
        ggxcl::Sampler& s = require(sampler, "sampler").sampler;
        const SampleParams p = to_params(params);
        const ggxcl::SampleRange r = to_range(range);
        const std::size_t floats = s.furnace_items(r.count) * (p.eta != 0.0f ? 3 : 2);
        PlacedBuffers placed(s.context(), sampler->base_align_bytes);
        const cl::Buffer sums_buffer = placed.output(sums, "sums", 1, floats, floats);
        const DeviceInputs in = place_inputs(placed, inputs, p, r.count, 0);  // no stride of their own
        enqueue_placed(queue, placed, wait_count, wait, event, [&](cl::CommandQueue& q, const std::vector<cl::Event>& w) {
            return s.enqueue_furnace(q, p, r, sums_buffer, in, or_null(w));
        });
    });
}

size_t ggxcl_furnace_items(const ggxcl_sampler* sampler, uint64_t count)
{
    return sampler ? sampler->sampler.furnace_items(count) : 0;
}

} // extern "C"
