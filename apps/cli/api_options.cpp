// api_options.cpp - --api, --shader-language and the vulkan: prefix.
#include "api_options.hpp"

#include "cli_values.hpp"

namespace ggxapp {

namespace {
const std::string vulkan_prefix = "vulkan:";
}

std::string ApiChoice::name() const
{
    return vulkan ? std::string("vulkan (") + ggxcl::shader_language_name(language) + ")" : "opencl";
}

std::string ApiChoice::device_label(const std::string& device_name) const
{
    return vulkan ? device_name + " (" + name() + ")" : device_name;
}

void ApiChoice::refuse_user_samplers(const std::vector<std::string>& files) const
{
    if (vulkan && !files.empty())
        throw UsageError("--sampler", files.front(),
                         "a built-in --method with --api vulkan (user samplers run on OpenCL for now)");
}

void ApiOptions::add_to(CLI::App& cmd)
{
    api_option = cmd.add_option("--api", api,
                                "opencl or vulkan: the API the samplers run on (vulkan: compute shaders compiled "
                                "from the same headers; a --device of vulkan:NAME implies it)")
                     ->capture_default_str();
    language_option = cmd.add_option("--shader-language", shader_language,
                                     "glsl or hlsl: the language of the Vulkan shaders (with --api vulkan)")
                          ->capture_default_str();
}

ApiChoice ApiOptions::choose(const std::string& device) const
{
    ApiChoice choice;
    if (api != "opencl" && api != "vulkan")
        throw UsageError("--api", api, "opencl or vulkan");
    const bool prefixed = device.rfind(vulkan_prefix, 0) == 0;
    if (prefixed && api_option && api_option->count() > 0 && api == "opencl")
        throw UsageError("--device", device, "an OpenCL device with --api opencl (`ggx devices` lists both)");
    choice.vulkan = api == "vulkan" || prefixed;
    choice.selector = prefixed ? device.substr(vulkan_prefix.size()) : device;
    try {
        choice.language = ggxcl::parse_shader_language(shader_language);
    } catch (const ggxcl::InvalidArgument&) {
        throw UsageError("--shader-language", shader_language, "glsl or hlsl");
    }
    if (!choice.vulkan && language_option && language_option->count() > 0)
        throw UsageError("--shader-language", shader_language, "nothing without --api vulkan (OpenCL runs OpenCL C)");
    return choice;
}

} // namespace ggxapp
