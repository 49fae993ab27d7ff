// backend_fixture.cpp - the back end of GGX_TEST_API, opened once.
#include "backend_fixture.hpp"

#include <cstdlib>
#include <memory>
#include <string>

#include "device_fixture.hpp"
#include "skip.hpp"

namespace ggxtest {

namespace {

std::string environment(const char* name, const char* fallback)
{
    const char* value = std::getenv(name);
    return value && *value ? value : fallback;
}

// Opened at the first call and never destroyed: the runtime's Vulkan instance outlives it.
ggxcl::Backend* open_vulkan()
{
    static ggxcl::Backend* vulkan = [] () -> ggxcl::Backend* {
        if (!ggxcl::vulkan_built())
            return nullptr;
        try {
            const ggxcl::ShaderLanguage language =
                ggxcl::parse_shader_language(environment("GGX_TEST_SHADER_LANGUAGE", "glsl"));
            return ggxcl::open_backend(ggxcl::Api::vulkan, "", language).release();
        } catch (const ggxcl::DeviceError&) {
            return nullptr;
        }
    }();
    return vulkan;
}

} // namespace

ggxcl::Backend* test_backend()
{
    const ggxcl::Api api = ggxcl::parse_api(environment("GGX_TEST_API", "opencl"));
    if (api == ggxcl::Api::opencl)
        return &sampler();
    ggxcl::Backend* vulkan = open_vulkan();
    if (!skip_unless(vulkan != nullptr, "needs a Vulkan device: a ggxcl built with Vulkan (libvulkan-dev, "
                                       "libshaderc-dev) and a driver (apt-get install mesa-vulkan-drivers)"))
        return nullptr;
    return vulkan;
}

} // namespace ggxtest
