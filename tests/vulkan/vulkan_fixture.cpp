// vulkan_fixture.cpp - the Vulkan suites' samplers (vulkan_fixture.hpp).
#include "vulkan_fixture.hpp"

namespace ggxvk {

ggxcl::VulkanSampler& vulkan_sampler(ggxcl::ShaderLanguage language)
{
    // Destroyed at exit, before nothing they need: the runtime's Vulkan instance is never destroyed.
    static ggxcl::VulkanSampler glsl("", ggxcl::ShaderLanguage::glsl), hlsl("", ggxcl::ShaderLanguage::hlsl);
    return language == ggxcl::ShaderLanguage::hlsl ? hlsl : glsl;
}

} // namespace ggxvk
