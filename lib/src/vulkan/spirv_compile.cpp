// spirv_compile.cpp - shaderc over the embedded sources, and the SPIR-V cache.
#include "spirv_compile.hpp"

#include <cstring>
#include <sstream>

#include <shaderc/shaderc.hpp>

#include "binary_cache.hpp"
#include "cache_roots.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/kernel_sources.hpp"
#include "ggxcl/version.hpp"

namespace ggxcl::detail {

namespace {

// The whole text shaderc compiles: the embedded file's includes are already
// expanded, framed by `#line N "file"` markers (GLSL reads them through
// GL_GOOGLE_cpp_style_line_directive).
std::string shader_text(ShaderLanguage language, const std::string& file)
{
    const std::string& body = kernel_source(file);
    if (language == ShaderLanguage::hlsl)
        return body;
    return "#version 450\n#extension GL_GOOGLE_cpp_style_line_directive : require\n" + body;
}

std::string cache_key(ShaderLanguage language, const std::string& file, const ShaderDefines& defines,
                      const std::string& text)
{
    std::string key = std::string("ggxcl ") + version() + " spirv-1.3 " + shader_language_name(language) + " " + file;
    for (const auto& [name, value] : defines)
        key += " " + name + "=" + std::to_string(value);
    return key + "\n" + text;
}

// The first line of shaderc's messages that holds "error", else the first line.
std::string first_error(const std::string& log)
{
    std::istringstream lines(log);
    std::string line, first;
    while (std::getline(lines, line)) {
        if (first.empty())
            first = line;
        if (line.find("error") != std::string::npos)
            return line;
    }
    return first;
}

std::vector<std::uint32_t> run_shaderc(ShaderLanguage language, const std::string& file,
                                       const ShaderDefines& defines, const std::string& text)
{
    shaderc::CompileOptions options;
    options.SetSourceLanguage(language == ShaderLanguage::hlsl ? shaderc_source_language_hlsl
                                                               : shaderc_source_language_glsl);
    options.SetTargetEnvironment(shaderc_target_env_vulkan, shaderc_env_version_vulkan_1_1);
    options.SetTargetSpirv(shaderc_spirv_version_1_3);
    options.SetOptimizationLevel(shaderc_optimization_level_performance);
    if (language == ShaderLanguage::hlsl)
        options.AddMacroDefinition("GGX_HLSL", "1");
    std::string define_text;
    for (const auto& [name, value] : defines) {
        options.AddMacroDefinition(name, std::to_string(value));
        define_text += (define_text.empty() ? "-D" : " -D") + name + "=" + std::to_string(value);
    }
    shaderc::Compiler compiler;
    const shaderc::SpvCompilationResult result =
        compiler.CompileGlslToSpv(text, shaderc_compute_shader, file.c_str(), "main", options);
    if (result.GetCompilationStatus() != shaderc_compilation_status_success) {
        const std::string log = result.GetErrorMessage();
        throw BuildError(first_error(log) + "\nshaderc could not compile " + file + " as " +
                             shader_language_name(language) + " with " + define_text,
                         log);
    }
    return {result.cbegin(), result.cend()};
}

// `text` compiled, or read from the disk cache.
CompiledShader compiled_text(ShaderLanguage language, const std::string& file, const ShaderDefines& defines,
                             const std::string& text)
{
    const std::string key = cache_key(language, file, defines, text);
    std::vector<unsigned char> bytes;
    CompiledShader shader;
    if (load_program_binary(key, bytes) && !bytes.empty() && bytes.size() % 4 == 0) {
        shader.spirv.resize(bytes.size() / 4);
        std::memcpy(shader.spirv.data(), bytes.data(), bytes.size());
        shader.from_disk = true;
        return shader;
    }
    shader.spirv = run_shaderc(language, file, defines, text);
    bytes.resize(shader.spirv.size() * 4);
    std::memcpy(bytes.data(), shader.spirv.data(), bytes.size());
    store_program_binary(key, bytes);
    return shader;
}

} // namespace

CompiledShader compile_shader(ShaderLanguage language, const std::string& file, const ShaderDefines& defines)
{
    return compiled_text(language, file, defines, shader_text(language, file));
}

CompiledShader compile_user_shader(const UserSampler& user, const std::string& file, const ShaderDefines& defines)
{
    const ShaderLanguage language = user.shader_language().value_or(ShaderLanguage::glsl);
    try {
        return compiled_text(language, file, defines, shader_text(language, file) + "\n" + user.source());
    } catch (const BuildError& error) {
        throw BuildError(user_build_summary(error.log()) + "\n(" + user.path() + " as " +
                             user.language_name() + ", in " + file + ")",
                         error.log());
    }
}

} // namespace ggxcl::detail
