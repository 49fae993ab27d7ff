// backend.cpp - opening a back end by API, and the names reports give it.
#include "ggxcl/backend.hpp"

#include "ggxcl/error.hpp"
#include "ggxcl/sampler.hpp"
#include "ggxcl/vulkan.hpp"

namespace ggxcl {

const char* api_name(Api api)
{
    return api == Api::vulkan ? "vulkan" : "opencl";
}

Api parse_api(const std::string& name)
{
    if (name == "opencl")
        return Api::opencl;
    if (name == "vulkan")
        return Api::vulkan;
    throw InvalidArgument("api", name, "opencl or vulkan");
}

std::string Backend::api_label() const
{
    const std::optional<ShaderLanguage> language = shader_language();
    return language ? std::string(api_name(api())) + " (" + shader_language_name(*language) + ")" : api_name(api());
}

std::string Backend::device_label() const
{
    return api() == Api::opencl ? device_name() : device_name() + " (" + api_label() + ")";
}

std::unique_ptr<Backend> open_backend(Api api, const std::string& selector, ShaderLanguage language)
{
    if (api == Api::vulkan)
        return std::make_unique<VulkanSampler>(selector, language);
    return std::make_unique<Sampler>(selector);
}

} // namespace ggxcl
