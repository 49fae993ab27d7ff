// vulkan_sampler_state.hpp - what VulkanSampler's parts share
// (vulkan_sampler.cpp: sampling, pdf and eval; vulkan_jobs.cpp: histogram,
// furnace, stress): its Vulkan objects and pipelines (VulkanSampler::State),
// the request's push constants made from ggx_contract.h's list, and the
// helpers every dispatch uses.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "device_contract.hpp"
#include "planar_inputs.hpp"
#include "program_variant.hpp"
#include "spirv_compile.hpp"
#include "spirv_features.hpp"
#include "vulkan_compute.hpp"
#include "vulkan_instance.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/user_sampler.hpp"
#include "ggxcl/vulkan.hpp"

namespace ggxcl {

namespace detail {

constexpr std::uint32_t group_size = 64;  // invocations per work-group: Vulkan promises at least 128

// The push constants of the bulk shader, from the list both sides read.
struct BulkRequest {
    using uint = std::uint32_t;
    GGX_BULK_REQUEST_MEMBERS
};
static_assert(sizeof(BulkRequest) == GGX_BULK_REQUEST_WORDS * 4, "ggx_contract.h: the push constants are 32-bit words");

inline std::uint32_t low_word(std::uint64_t v) { return std::uint32_t(v); }
inline std::uint32_t high_word(std::uint64_t v) { return std::uint32_t(v >> 32); }

// vk::SystemError (a std::system_error) as ggxcl's errors.
template <typename Call>
auto translate_vulkan_errors(const std::string& device, Call&& call)
{
    try {
        return call();
    } catch (const vk::DeviceLostError& e) {
        throw DeviceError("the Vulkan device '" + device + "' was lost (" + e.what() +
                          "); the results of this call are incomplete");
    } catch (const vk::SystemError& e) {
        throw DeviceError("a Vulkan call on '" + device + "' failed: " + e.what());
    }
}

// A user sampler's file in the language Vulkan compiles: InvalidArgument for one in OpenCL C.
inline void check_shader_sampler(const UserSampler& user)
{
    if (!user.shader_language())
        throw InvalidArgument("sampler", user.path(),
                              "a user sampler in GLSL or HLSL on Vulkan (this file is OpenCL C: it runs on Sampler; "
                              "UserSampler::load reads it as a shader with a shader language)");
}

// Entries [done, done + n) of the caller's per-sample inputs as planes of
// stride `capacity`, one input after another in `inputs`, their offsets in
// `request`; returns the floats used.
inline std::uint32_t put_inputs(const PerSampleInputs& in, std::uint64_t done, std::uint64_t n, std::uint64_t capacity,
                         MappedBuffer& inputs, BulkRequest& request)
{
    std::uint32_t at = 0;
    auto put = [&](std::uint32_t& offset, const std::vector<float>& planes) {
        offset = at;
        std::memcpy(inputs.data + at, planes.data(), planes.size() * sizeof(float));
        at += std::uint32_t(planes.size());
    };
    if (!in.views.empty()) put(request.view_at, planar_units(in.views, done, n, capacity));
    if (!in.alphas.empty()) put(request.alpha_at, planar_pairs(in.alphas, done, n, capacity));
    if (!in.normals.empty()) put(request.normal_at, planar_units(in.normals, done, n, capacity));
    if (!in.uniforms.empty()) put(request.uniforms_at, planar_uniforms(in, done, n, capacity));
    return at;
}

// The push constants every shader reads of a request: its seed and uniform parameters.
inline BulkRequest request_of(const SampleParams& p, std::uint64_t seed)
{
    BulkRequest request{};
    request.seed_lo = low_word(seed);
    request.seed_hi = high_word(seed);
    request.view_x = p.view.x, request.view_y = p.view.y, request.view_z = p.view.z;
    request.alpha_x = p.alpha_x, request.alpha_y = p.alpha_y;
    request.normal_x = p.normal.x, request.normal_y = p.normal.y, request.normal_z = p.normal.z;
    request.eta = p.eta;
    return request;
}

} // namespace detail

struct VulkanSampler::State {
    std::shared_ptr<detail::VulkanInstance> vulkan;
    std::unique_ptr<detail::VulkanCompute> compute;
    ShaderLanguage language = ShaderLanguage::glsl;
    std::atomic<std::uint64_t> chunk_size{1u << 20};
    // Calls from several threads run one after another: they share the queue, the pipelines and
    // the counters (recursive: a sink may call the sampler again from the same thread).
    std::recursive_mutex calls;
    std::map<std::string, vk::raii::Pipeline> pipelines;  // by program and defines
    std::size_t from_disk = 0;

    // The pipeline of shader `program` (kernels/<program>.comp or .hlsl) built with `defines`;
    // with a user sampler, in its file's language with its file after the program's text
    // (as OpenCL's user programs, ggx_user_sampler.h).
    const vk::raii::Pipeline& shader_pipeline(const std::string& program, detail::ShaderDefines defines,
                                              const UserSampler* user = nullptr)
    {
        defines.emplace_back("GGX_GROUP_SIZE", long(detail::group_size));
        ShaderLanguage shader_language = language;
        if (user) {
            detail::check_shader_sampler(*user);
            shader_language = *user->shader_language();
            defines.emplace_back("GGX_USER_SAMPLER", 1);
            defines.emplace_back("GGX_USER_SAMPLES_M", user->samples_m() ? 1 : 0);
        }
        std::string key = program + " " + shader_language_name(shader_language) + (user ? " " + user->key() : "");
        for (const auto& [name, value] : defines)
            key += " " + name + "=" + std::to_string(value);
        auto found = pipelines.find(key);
        if (found != pipelines.end())
            return found->second;
        const std::string file = program + (shader_language == ShaderLanguage::hlsl ? ".hlsl" : ".comp");
        const detail::CompiledShader shader =
            user ? detail::compile_user_shader(*user, file, defines) : detail::compile_shader(shader_language, file, defines);
        from_disk += shader.from_disk ? 1 : 0;
        const std::string missing = user ? detail::missing_device_feature(shader.spirv, compute->info()) : "";
        if (!missing.empty())
            throw BuildError(user->path() + ": the user sampler cannot run here: " + missing, "");
        return pipelines.emplace(key, compute->pipeline(shader.spirv)).first->second;
    }

    // A request variant's: the shader of its kind with its switches (and its user sampler).
    const vk::raii::Pipeline& pipeline(const detail::ProgramVariant& variant, std::string program = "")
    {
        if (program.empty())
            program = std::string("ggx_") + detail::program_kind_name(variant.kind);
        return shader_pipeline(program, detail::variant_define_list(variant), variant.user.get());
    }

    // Runs `pipeline` over `invocations` (a 2-D dispatch where the device
    // caps work-groups per dimension: request.row_width set to its rows'
    // width) with `request` as push constants; waits.
    void dispatch(const vk::raii::Pipeline& pipeline, detail::BulkRequest& request, std::uint64_t invocations,
                  const detail::MappedBuffer& inputs, const detail::MappedBuffer& outputs)
    {
        const VulkanDeviceInfo& info = compute->info();
        const detail::DispatchShape shape =
            detail::dispatch_shape(invocations, detail::group_size, info.max_work_groups_x, info.max_work_groups_y);
        request.row_width = shape.row_width;
        compute->dispatch(pipeline, &request, sizeof request, inputs, outputs, shape);
    }

    // Samples per chunk of a call of `count`: the chunk size, within one storage buffer of the
    // device, and no more than the call needs (its buffers are made per call).
    std::uint64_t capacity(std::uint64_t floats_per_sample, std::uint64_t count) const
    {
        const std::uint64_t range = compute->info().max_storage_buffer_range / sizeof(float);
        return std::max<std::uint64_t>(1, std::min({count, chunk_size.load(), range / std::max<std::uint64_t>(floats_per_sample, 1)}));
    }
};

} // namespace ggxcl
