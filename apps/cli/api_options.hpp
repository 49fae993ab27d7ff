// api_options.hpp - which API a command runs on: --api opencl|vulkan,
// --shader-language glsl|hlsl (Vulkan), a --device selector's "vulkan:"
// prefix (`--device vulkan:llvmpipe` is `--api vulkan --device llvmpipe`),
// and a --sampler FILE.glsl or FILE.hlsl, which runs on Vulkan.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <ggxcl/ggxcl.hpp>

namespace ggxapp {

struct ApiChoice {
    ggxcl::Api api = ggxcl::Api::opencl;
    std::string selector;  // the device selector without its prefix
    ggxcl::ShaderLanguage language = ggxcl::ShaderLanguage::glsl;  // of the built-in methods' shaders
    // The language a --sampler FILE is read in: none (OpenCL C) on OpenCL;
    // on Vulkan its extension's (.glsl, .hlsl), else `language`.
    std::optional<ggxcl::ShaderLanguage> sampler_language(const std::string& file) const;
    // The back end of this choice on its device: the one place a command opens one.
    std::unique_ptr<ggxcl::Backend> open() const;
    // The options that choose it again in a child `ggx` process (--api, --shader-language, --device).
    std::vector<std::string> arguments() const;
};

// Of several APIs' choices, the one that reads a --sampler `file`: Vulkan's for a .glsl or .hlsl
// file, else OpenCL's where there is one, else the first.
const ApiChoice& choice_for_file(const std::string& file, const std::vector<ApiChoice>& choices);

struct ApiOptions {
    std::string api = "opencl", shader_language = "glsl";
    CLI::Option* api_option = nullptr;
    CLI::Option* language_option = nullptr;

    void add_to(CLI::App& cmd);
    // The choice for `device` (the command's --device) and the command's
    // --sampler files: a .glsl or .hlsl file implies Vulkan, and without
    // --shader-language the first such file's language is the built-ins'.
    // UsageError for an unknown API or language, --shader-language without
    // Vulkan or against a file's extension, or --api opencl with a vulkan:
    // selector or a shader file.
    ApiChoice choose(const std::string& device, const std::vector<std::string>& sampler_files = {}) const;
    // `ggx bench`'s --api, a list (opencl,vulkan): one API as choose(); with both, `device` chooses
    // OpenCL's device, or with the vulkan: prefix Vulkan's, and the other API's is its default.
    std::vector<ApiChoice> choose_list(const std::string& device, const std::vector<std::string>& sampler_files) const;
};

} // namespace ggxapp
