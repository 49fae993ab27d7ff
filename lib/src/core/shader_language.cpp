// shader_language.cpp - the names of the shading languages (built with or
// without the Vulkan back end).
#include "ggxcl/error.hpp"
#include "ggxcl/shader_language.hpp"

namespace ggxcl {

const char* shader_language_name(ShaderLanguage language)
{
    return language == ShaderLanguage::hlsl ? "hlsl" : "glsl";
}

ShaderLanguage parse_shader_language(const std::string& name)
{
    if (name == "glsl")
        return ShaderLanguage::glsl;
    if (name == "hlsl")
        return ShaderLanguage::hlsl;
    throw InvalidArgument("shader language", name, "glsl or hlsl");
}

} // namespace ggxcl
