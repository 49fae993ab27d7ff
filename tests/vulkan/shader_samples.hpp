// shader_samples.hpp - the sample shaders of tests/vulkan/shaders (GLSL and
// HLSL) run on the Vulkan device for one request, and the same request on
// the OpenCL device from the same uniforms, as ggxcl::SampleSets that the
// comparisons and histograms of the other suites read.
#pragma once

#include <cstdint>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "shader_compiler.hpp"
#include "compute_device.hpp"

namespace ggxvk {

// The Vulkan device all shader tests share.
ComputeDevice& vulkan();

// The SPIR-V of the sample shader of `method` in `language` (compiled once).
const std::vector<std::uint32_t>& sample_shader(ShaderLanguage language, ggxcl::Method method, bool dielectric);

// Uniforms in [0, 1) on the 24-bit grid, as planes u1, u2, u3 (3 count floats).
std::vector<float> random_uniforms(std::uint64_t seed, std::uint64_t count);

// The shader's samples of `params` (tangent space, normal +z; eta != 0: a
// dielectric) from `uniforms`, with the pdf of each o recomputed in `pdf`.
struct ShaderSamples {
    ggxcl::SampleSet set;
    std::vector<float> pdf;
};
ShaderSamples shader_samples(ShaderLanguage language, const ggxcl::SampleParams& params,
                             const std::vector<float>& uniforms);

// The OpenCL device's samples of `params` from the same uniforms.
ggxcl::SampleSet opencl_samples(const ggxcl::SampleParams& params, const std::vector<float>& uniforms);

} // namespace ggxvk
