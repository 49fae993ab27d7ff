// api_options.hpp - which API a command runs on: --api opencl|vulkan,
// --shader-language glsl|hlsl (Vulkan), and a --device selector's
// "vulkan:" prefix (`--device vulkan:llvmpipe` is `--api vulkan --device llvmpipe`).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <ggxcl/ggxcl.hpp>

namespace ggxapp {

struct ApiChoice {
    bool vulkan = false;
    std::string selector;  // the device selector without its prefix
    ggxcl::ShaderLanguage language = ggxcl::ShaderLanguage::glsl;
    std::string name() const;  // "opencl", or "vulkan (glsl)"
    // How reports name the device: "NAME", or on Vulkan "NAME (vulkan (glsl))".
    std::string device_label(const std::string& device_name) const;
    // UsageError naming --sampler when Vulkan is chosen with user samplers
    // (they run on OpenCL for now); `files` may be empty.
    void refuse_user_samplers(const std::vector<std::string>& files) const;
};

struct ApiOptions {
    std::string api = "opencl", shader_language = "glsl";
    CLI::Option* api_option = nullptr;
    CLI::Option* language_option = nullptr;

    void add_to(CLI::App& cmd);
    // The choice for `device` (the command's --device); UsageError for an
    // unknown API or language, --shader-language without Vulkan, or
    // --api opencl with a vulkan: selector.
    ApiChoice choose(const std::string& device) const;
};

} // namespace ggxapp
