// vulkan.hpp - ggxcl on Vulkan: the requests of Sampler run as compute
// shaders that shaderc compiles at run time from the same device headers, in
// GLSL or HLSL, on any Vulkan 1.1 device with 64-bit integers in shaders
// (desktop GPUs, Mesa's lavapipe on the CPU, MoltenVK).  The Vulkan loader
// is opened at run time: a machine without it gets a DeviceError saying
// what to install, not a program that cannot start.
//
//   ggxcl::VulkanSampler vk;                         // GGXCL_VULKAN_DEVICE or the first device
//   ggxcl::SampleSet s = vk.generate(params, {1, 0, 1 << 20}, {ggxcl::Field::o, ggxcl::Field::pdf_o});
//
// The same request and range give the same uniforms as Sampler, and samples
// that agree with OpenCL's within float rounding (docs/SHADERS.md).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ggxcl/fields.hpp"
#include "ggxcl/params.hpp"
#include "ggxcl/backend.hpp"
#include "ggxcl/results.hpp"
#include "ggxcl/shader_language.hpp"
#include "ggxcl/user_sampler.hpp"

namespace ggxcl {

struct VulkanDeviceInfo {
    std::size_t index = 0;  // position in list_vulkan_devices(): a valid selector
    std::string name;       // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string type;       // "GPU", "integrated GPU", "CPU", "virtual GPU" or "other"
    std::string api_version, driver;  // "1.3.238"; the driver's name and version
    std::uint32_t max_storage_buffer_range = 0;  // bytes one storage buffer binding may span
    std::uint32_t max_work_groups_x = 0, max_work_groups_y = 0;  // work-groups per dispatch dimension
    std::uint32_t max_push_constants = 0;  // bytes
    std::uint32_t max_shared_memory = 0;   // bytes of shared memory per work-group
    bool int64 = false;  // shaderInt64: without it the samplers cannot run (Philox, Sobol)
    // What a user's shader may use beside: shaderFloat16, shaderInt8 (VK_KHR_shader_float16_int8),
    // shaderInt16, 16-bit storage buffer access; each enabled where the device has it.
    bool float16 = false, int8 = false, int16 = false, storage16 = false;
    // "vulkan:<name>", how the CLI names it beside OpenCL devices.
    std::string label() const { return "vulkan:" + name; }
};

// Whether this build of ggxcl has the Vulkan back end (CMake found Vulkan-Hpp and shaderc).
bool vulkan_built();

// Every Vulkan device.  DeviceError when the build has no Vulkan, the loader
// (libvulkan.so.1) is missing or no driver offers a device, saying what to install.
std::vector<VulkanDeviceInfo> list_vulkan_devices();

// The device a selector names: an index into list_vulkan_devices() or a
// case-insensitive part of its name; empty means GGXCL_VULKAN_DEVICE, else
// the first device.  NoMatchingDevice lists what exists when nothing matches.
VulkanDeviceInfo select_vulkan_device(const std::string& selector = "");

// Samples on a Vulkan device, into host memory, chunk by chunk.  Shaders
// are built per request variant (the switches of the OpenCL programs) and
// cached on disk as SPIR-V beside the OpenCL binaries (GGXCL_PROGRAM_CACHE).
// A shader that does not compile is a BuildError naming its file and line.
// User samplers in GLSL or HLSL (UserSampler::load of a .glsl or .hlsl file)
// run in every call in place of a method, in their file's language; one in
// OpenCL C is InvalidArgument.  Not yet on Vulkan: the caller's buffers.
// Threads: as every Backend, it takes calls from several threads at once;
// they run one after another (its queue and buffers are shared), each with
// the bits it gives alone.
class VulkanSampler : public Backend {
public:
    explicit VulkanSampler(const std::string& selector = "", ShaderLanguage language = ShaderLanguage::glsl);
    ~VulkanSampler();
    VulkanSampler(VulkanSampler&&) noexcept;
    VulkanSampler& operator=(VulkanSampler&&) noexcept;

    const VulkanDeviceInfo& device() const;
    Api api() const override { return Api::vulkan; }
    std::optional<ShaderLanguage> shader_language() const override { return language(); }
    std::string device_name() const override;  // "vulkan:<name>"
    ShaderLanguage language() const;

    // Samples per dispatch (default 2^20), lowered where the device's
    // storage buffers are smaller; results do not depend on it.
    void set_chunk_size(std::uint64_t samples) override;
    std::uint64_t chunk_size() const override;
    std::size_t work_group_size() const override;  // the shaders' local size (64)

    SampleSet generate(const SampleParams& params, const SampleRange& range, FieldSet fields,
                       const PerSampleInputs& per_sample = {}) override;
    void generate_chunks(const SampleParams& params, const SampleRange& range, FieldSet fields,
                         const ChunkSink& sink, const PerSampleInputs& per_sample = {}) override;
    // The same without a copy: each chunk's planes where the device wrote
    // them (stride >= count), valid during the call of `sink`.
    void generate_chunk_views(const SampleParams& params, const SampleRange& range, FieldSet fields,
                              const ChunkViewSink& sink, const PerSampleInputs& per_sample = {}) override;

    // The pdf, and the BSDF value f |cos|, of each direction o, as
    // Sampler::pdf and Sampler::eval (kernels/ggx_pdf.comp or .hlsl).
    std::vector<float> pdf(const SampleParams& params, const std::vector<Vec3>& directions,
                           const PerSampleInputs& per_sample = {}) override;
    std::vector<float> eval(const SampleParams& params, const std::vector<Vec3>& directions,
                            const PerSampleInputs& per_sample = {}) override;

    // Bins the directions (Field::o or Field::m) of `range` on the device, as
    // Sampler::histogram: only the counts come back; bins_z * bins_phi + 2
    // counters fit the device's shared memory (InvalidArgument otherwise).
    Histogram histogram(const SampleParams& params, const SampleRange& range, int bins_z, int bins_phi,
                        Field direction = Field::o) override;

    // The fused white-furnace estimator, as Sampler::furnace: the same
    // samples per invocation, so the sums do not depend on the chunk size.
    FurnaceSums furnace(const SampleParams& params, const SampleRange& range) override;

    // The stability map's cases (Backend::stress): kernels/ggx_stress.comp or
    // .hlsl; a user sampler in GLSL or HLSL.  One SPIR-V for every precision.
    std::vector<float> stress(const StressRequest& request, const std::vector<float>& in,
                              std::uint32_t count) override;

    std::size_t shaders_built() const;     // pipelines made so far
    std::size_t shaders_from_disk() const;  // of those, SPIR-V read from the cache

    struct State;  // the Vulkan objects (lib/src/vulkan/)

private:
    std::vector<float> of_directions(const SampleParams& params, const std::vector<Vec3>& directions,
                                     const PerSampleInputs& per_sample, bool eval);
    std::unique_ptr<State> state_;
};

} // namespace ggxcl
