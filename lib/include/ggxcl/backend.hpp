// backend.hpp - what every back end of ggxcl does, whatever its API: draw
// samples (whole, in chunks, as views), evaluate pdfs and BSDF values, bin
// histograms, sum the white furnace and run the stability map's cases.
// Sampler (OpenCL, sampler.hpp) and VulkanSampler (vulkan.hpp) implement it;
// open_backend() picks one from an API and a device selector, so a program
// chooses once and writes the rest once.
//
//   std::unique_ptr<ggxcl::Backend> b = ggxcl::open_backend(ggxcl::Api::vulkan);
//   ggxcl::FurnaceSums f = b->furnace(params, {1, 0, 1 << 20});
//
// Threads: every member may be called from several threads at once, each
// call giving the bits it gives alone (docs/LIBRARY.md "Threads").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ggxcl/fields.hpp"
#include "ggxcl/params.hpp"
#include "ggxcl/results.hpp"
#include "ggxcl/shader_language.hpp"
#include "ggxcl/user_sampler.hpp"

namespace ggxcl {

enum class Api { opencl, vulkan };
inline constexpr std::array<Api, 2> all_apis = {Api::opencl, Api::vulkan};
const char* api_name(Api api);  // "opencl", "vulkan"
Api parse_api(const std::string& name);  // a name of api_name; InvalidArgument("api", ...) otherwise

// One run of the stability map's kernel or shader (`ggx stress`, kernels/ggx_stress.cl, .comp,
// .hlsl): `method` with or without the guards, a rough dielectric's with `dielectric`;
// Method::user runs `user` (a conductor's map).  `precision` selects OpenCL's build options
// (Vulkan builds one SPIR-V for every mode).
struct StressRequest {
    Method method = Method::caps;
    Precision precision = Precision::precise;
    bool guards = true;
    bool dielectric = false;
    const UserSampler* user = nullptr;
};

class Backend {
public:
    using ChunkSink = ggxcl::ChunkSink;
    using ChunkViewSink = ggxcl::ChunkViewSink;
    virtual ~Backend() = default;

    virtual Api api() const = 0;
    // The language of its built-in shaders: none on OpenCL (OpenCL C), GLSL or HLSL on Vulkan.
    virtual std::optional<ShaderLanguage> shader_language() const = 0;
    virtual std::string device_name() const = 0;  // OpenCL: the device's name; Vulkan: "vulkan:<name>"
    std::string api_label() const;     // "opencl", or "vulkan (glsl)"
    std::string device_label() const;  // how reports name it: "NAME", or "NAME (vulkan (glsl))"

    // Samples per device pass; memory stays bounded by it and results do not depend on it.
    virtual void set_chunk_size(std::uint64_t samples) = 0;
    virtual std::uint64_t chunk_size() const = 0;
    // Work-items (invocations) per work-group of its launches; results do not depend on it.
    virtual std::size_t work_group_size() const = 0;

    // The samples of `range` into host vectors.
    virtual SampleSet generate(const SampleParams& params, const SampleRange& range, FieldSet fields,
                               const PerSampleInputs& per_sample = {}) = 0;
    // Chunk by chunk (chunk_size() at most), each handed to `sink` with its offset in the range.
    virtual void generate_chunks(const SampleParams& params, const SampleRange& range, FieldSet fields,
                                 const ChunkSink& sink, const PerSampleInputs& per_sample = {}) = 0;
    // The same without a copy where the back end can: each chunk where the device wrote it.
    virtual void generate_chunk_views(const SampleParams& params, const SampleRange& range, FieldSet fields,
                                      const ChunkViewSink& sink, const PerSampleInputs& per_sample = {}) = 0;

    // The pdf (per steradian) and the BSDF value f |cos theta_o| of each direction o.
    virtual std::vector<float> pdf(const SampleParams& params, const std::vector<Vec3>& directions,
                                   const PerSampleInputs& per_sample = {}) = 0;
    virtual std::vector<float> eval(const SampleParams& params, const std::vector<Vec3>& directions,
                                    const PerSampleInputs& per_sample = {}) = 0;

    // Bins the directions (Field::o or Field::m) of `range` on the device: only the counts come back.
    virtual Histogram histogram(const SampleParams& params, const SampleRange& range, int bins_z, int bins_phi,
                                Field direction = Field::o) = 0;
    // The fused white-furnace estimator's sums over `range`.
    virtual FurnaceSums furnace(const SampleParams& params, const SampleRange& range) = 0;

    // The stability map's cases: `count` cases of planar inputs (in[k * count + j]: 10 planes,
    // 12 for a dielectric); returns the output planes (10, 11 for a dielectric) alike.
    virtual std::vector<float> stress(const StressRequest& request, const std::vector<float>& in,
                                      std::uint32_t count) = 0;
};

// A back end on `api`'s device that `selector` names (an index or a part of
// its name; empty: GGXCL_DEVICE or GGXCL_VULKAN_DEVICE, else the first
// device); `language` is the Vulkan shaders'.  DeviceError where the API has
// no driver, NoMatchingDevice where nothing matches.
std::unique_ptr<Backend> open_backend(Api api, const std::string& selector = "",
                                      ShaderLanguage language = ShaderLanguage::glsl);

} // namespace ggxcl
