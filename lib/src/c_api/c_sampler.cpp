// c_sampler.cpp - the C API's samplers and user samplers, and the enqueue
// calls into the caller's buffers at their offsets on the caller's queue:
// the buffers and offsets go to the kernels as they are.
#include <cstring>
#include <string>

#include "c_api/c_events.hpp"
#include "c_api/c_handles.hpp"
#include "c_api/c_params.hpp"
#include "c_api/c_status.hpp"
#include "ggxcl/error.hpp"

using namespace ggxcl::capi;
using ggxcl::DeviceInputs;
using ggxcl::Field;
using ggxcl::SampleParams;

namespace {

// The caller's buffer at its offset, as the kernels take it (a NULL mem: none).
ggxcl::DeviceArray array_of(const ggxcl_buffer& buffer)
{
    return buffer.mem ? ggxcl::DeviceArray(cl::Buffer(buffer.mem, true), buffer.offset) : ggxcl::DeviceArray();
}

// The caller's per-sample inputs at their offsets.
DeviceInputs inputs_of(const ggxcl_device_inputs* inputs)
{
    DeviceInputs in;
    if (!inputs)
        return in;
    const ggxcl::DeviceArray view = array_of(inputs->view), alpha = array_of(inputs->alpha),
                             normal = array_of(inputs->normal), uniforms = array_of(inputs->uniforms);
    in.view = view.buffer, in.view_offset = view.offset;
    in.alpha = alpha.buffer, in.alpha_offset = alpha.offset;
    in.normal = normal.buffer, in.normal_offset = normal.offset;
    in.uniforms = uniforms.buffer, in.uniforms_offset = uniforms.offset;
    in.views_above_horizon = inputs->views_above_horizon != 0;
    in.isotropic = inputs->isotropic != 0;
    return in;
}

// Runs `launch(queue, wait)` on the caller's queue after the caller's events and hands its event over.
template <class Launch>
void enqueue_on(cl_command_queue queue, cl_uint wait_count, const cl_event* wait, cl_event* event, Launch&& launch)
{
    cl::CommandQueue caller_queue(non_null(queue, "queue"), true);
    const std::vector<cl::Event> events = wait_list(wait_count, wait);
    hand_over(launch(caller_queue, events.empty() ? nullptr : &events), event);
}

ggxcl_status enqueue_directions(ggxcl_sampler* sampler, cl_command_queue queue, const ggxcl_params* params,
                                uint32_t count, ggxcl_buffer directions, ggxcl_buffer out, uint32_t stride,
                                const ggxcl_device_inputs* inputs, cl_uint wait_count, const cl_event* wait,
                                cl_event* event, bool eval)
{
    return guarded([&] {
        ggxcl::Sampler& s = opencl_of(sampler, eval ? "ggxcl_enqueue_eval" : "ggxcl_enqueue_pdf");
        const SampleParams p = to_params(params);
        const DeviceInputs in = inputs_of(inputs);
        enqueue_on(queue, wait_count, wait, event, [&](cl::CommandQueue& q, const std::vector<cl::Event>* w) {
            return eval ? s.enqueue_eval(q, p, count, array_of(directions), array_of(out), stride, in, w)
                        : s.enqueue_pdf(q, p, count, array_of(directions), array_of(out), stride, in, w);
        });
    });
}

// What `get` reads of the OpenCL Sampler of `sampler` for `call`; on another API (or NULL) a zero
// value, with the last error naming the call.
template <class Get>
auto opencl_part(const ggxcl_sampler* sampler, const char* call, Get&& get) -> decltype(get(*sampler->opencl))
{
    decltype(get(*sampler->opencl)) value{};
    guarded([&] { value = get(opencl_of(sampler, call)); });
    return value;
}

} // namespace

extern "C" {

ggxcl_status ggxcl_sampler_create(const char* selector, ggxcl_sampler** sampler)
{
    return ggxcl_sampler_create_api(GGXCL_API_OPENCL, selector, GGXCL_SHADER_GLSL, sampler);
}

ggxcl_status ggxcl_sampler_create_api(ggxcl_api api_id, const char* selector, ggxcl_shader_language language_id,
                                      ggxcl_sampler** sampler)
{
    return guarded([&] {
        ggxcl_sampler*& out = require(sampler, "sampler");
        out = nullptr;
        // A C caller's enum may hold any int: read as int, not as the C++ enum (whose range is 0..1).
        static_assert(sizeof(ggxcl_api) == sizeof(int) && sizeof(ggxcl_shader_language) == sizeof(int));
        int api = 0, language = 0;
        std::memcpy(&api, &api_id, sizeof api);
        std::memcpy(&language, &language_id, sizeof language);
        if (api != GGXCL_API_OPENCL && api != GGXCL_API_VULKAN)
            throw ggxcl::InvalidArgument("api", std::to_string(api), "GGXCL_API_OPENCL or GGXCL_API_VULKAN");
        if (language != GGXCL_SHADER_GLSL && (api != GGXCL_API_VULKAN || language != GGXCL_SHADER_HLSL))
            throw ggxcl::InvalidArgument("language", std::to_string(language),
                                         "GGXCL_SHADER_GLSL, or GGXCL_SHADER_HLSL with GGXCL_API_VULKAN");
        const ggxcl::ShaderLanguage shaders =
            language == GGXCL_SHADER_HLSL ? ggxcl::ShaderLanguage::hlsl : ggxcl::ShaderLanguage::glsl;
        out = new ggxcl_sampler(ggxcl::open_backend(api == GGXCL_API_VULKAN ? ggxcl::Api::vulkan : ggxcl::Api::opencl,
                                                    selector ? selector : "", shaders));
    });
}

ggxcl_status ggxcl_sampler_create_with_context(cl_context context, cl_device_id device, ggxcl_sampler** sampler)
{
    return guarded([&] {
        ggxcl_sampler*& out = require(sampler, "sampler");
        out = nullptr;
        out = new ggxcl_sampler(std::make_unique<ggxcl::Sampler>(cl::Context(non_null(context, "context"), true),
                                                                 cl::Device(non_null(device, "device"), true)));
    });
}

void ggxcl_sampler_release(ggxcl_sampler* sampler) { delete sampler; }

ggxcl_api ggxcl_sampler_api(const ggxcl_sampler* sampler) { return sampler && !sampler->opencl ? GGXCL_API_VULKAN : GGXCL_API_OPENCL; }
cl_context ggxcl_sampler_context(const ggxcl_sampler* sampler)
{
    return opencl_part(sampler, "ggxcl_sampler_context", [](const ggxcl::Sampler& s) { return s.context()(); });
}
cl_device_id ggxcl_sampler_device(const ggxcl_sampler* sampler)
{
    return opencl_part(sampler, "ggxcl_sampler_device", [](const ggxcl::Sampler& s) { return s.device()(); });
}
cl_command_queue ggxcl_sampler_queue(const ggxcl_sampler* sampler)
{
    return opencl_part(sampler, "ggxcl_sampler_queue",
                       [](const ggxcl::Sampler& s) { return const_cast<ggxcl::Sampler&>(s).queue()(); });
}

const char* ggxcl_sampler_device_name(const ggxcl_sampler* sampler) { return sampler ? sampler->device_name.c_str() : ""; }

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
        ggxcl::Sampler& s = opencl_of(sampler, "ggxcl_enqueue");
        const SampleParams p = to_params(params);
        const ggxcl::SampleRange r = to_range(range);
        const ggxcl_device_outputs& out = require(outputs, "outputs");
        ggxcl::DeviceOutputs device_out;
        for (Field field : ggxcl::all_fields) {
            const ggxcl::DeviceArray array = array_of(output_of(out, field));
            device_out.of(field) = array.buffer;
            device_out.offset_of(field) = array.offset;
        }
        const DeviceInputs in = inputs_of(inputs);
        enqueue_on(queue, wait_count, wait, event, [&](cl::CommandQueue& q, const std::vector<cl::Event>* w) {
            return s.enqueue(q, p, r, device_out, stride, in, w);
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
        ggxcl::Sampler& s = opencl_of(sampler, "ggxcl_enqueue_furnace");
        const SampleParams p = to_params(params);
        const ggxcl::SampleRange r = to_range(range);
        const DeviceInputs in = inputs_of(inputs);
        enqueue_on(queue, wait_count, wait, event, [&](cl::CommandQueue& q, const std::vector<cl::Event>* w) {
            return s.enqueue_furnace(q, p, r, array_of(sums), in, w);
        });
    });
}

size_t ggxcl_furnace_items(const ggxcl_sampler* sampler, uint64_t count)
{
    return opencl_part(sampler, "ggxcl_furnace_items", [&](const ggxcl::Sampler& s) { return s.furnace_items(count); });
}

} // extern "C"
