// backend.cpp - opening a back end by API (each back end's opener: backend_factories.hpp), and the
// names reports give it.
#include "ggxcl/backend.hpp"

#include "backend_factories.hpp"
#include "named_values.hpp"

namespace ggxcl {

const char* api_name(Api api)
{
    return api == Api::vulkan ? "vulkan" : "opencl";
}

Api parse_api(const std::string& name)
{
    return detail::parse_named(name, all_apis, api_name, "api");
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
    return api == Api::vulkan ? detail::open_vulkan_backend(selector, language) : detail::open_opencl_backend(selector);
}

} // namespace ggxcl
