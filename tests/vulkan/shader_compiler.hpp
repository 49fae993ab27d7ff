// shader_compiler.hpp - GLSL and HLSL compute shaders to SPIR-V with shaderc
// (glslang's GLSL and HLSL front ends), the device headers reachable by
// #include "ggx_*.h" from the kernel folder.  A shader that does not compile
// throws with shaderc's messages, which name the file and the line.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <ggxcl/vulkan.hpp>

namespace ggxvk {

using ShaderLanguage = ggxcl::ShaderLanguage;
inline constexpr ShaderLanguage all_shader_languages[] = {ShaderLanguage::glsl, ShaderLanguage::hlsl};
inline const char* language_name(ShaderLanguage language) { return ggxcl::shader_language_name(language); }

struct ShaderSource {
    ShaderLanguage language = ShaderLanguage::glsl;
    std::string name;  // the file name the messages give
    std::string text;
    std::vector<std::pair<std::string, std::string>> defines;  // -D NAME=VALUE
};

// SPIR-V 1.3 for Vulkan 1.1 (glslang 12 decorates an HLSL RWStructuredBuffer
// with BufferBlock, which SPIR-V 1.4 and later refuse); `include_dirs` are
// searched in order for every #include.  HLSL sources get GGX_HLSL=1.
std::vector<std::uint32_t> compile_compute_shader(const ShaderSource& source,
                                                  const std::vector<std::string>& include_dirs);

// The text of a file, or an exception naming it.
std::string read_text_file(const std::string& path);

} // namespace ggxvk
