// shader_language.hpp - the shading languages ggxcl compiles for Vulkan
// (GLSL 4.50 and HLSL, both through shaderc): the shaders of VulkanSampler
// and the user samplers written in them (user_sampler.hpp).
#pragma once

#include <string>

namespace ggxcl {

enum class ShaderLanguage { glsl, hlsl };
const char* shader_language_name(ShaderLanguage language);  // "glsl", "hlsl"
// "glsl" or "hlsl"; InvalidArgument("shader language", ...) otherwise.
ShaderLanguage parse_shader_language(const std::string& name);

} // namespace ggxcl
