// vulkan_fixture.cpp - the Vulkan suites' samplers and requests (vulkan_fixture.hpp).
#include "vulkan_fixture.hpp"

namespace ggxvk {

ggxcl::VulkanSampler& vulkan_sampler(ggxcl::ShaderLanguage language)
{
    // Destroyed at exit, before nothing they need: the runtime's Vulkan instance is never destroyed.
    static ggxcl::VulkanSampler glsl("", ggxcl::ShaderLanguage::glsl), hlsl("", ggxcl::ShaderLanguage::hlsl);
    return language == ggxcl::ShaderLanguage::hlsl ? hlsl : glsl;
}

ggxcl::SampleParams chi_square_conductor(ggxcl::Method method)
{
    ggxcl::SampleParams p;
    p.method = method;
    p.alpha_x = 0.35f;
    p.alpha_y = ggxcl::method_traits(method).isotropic_only ? 0.35f : 0.7f;
    p.view = ggxcl::unit_vector({0.6f, 0.3f, 0.5f});
    return p;
}

ggxcl::SampleParams chi_square_dielectric(ggxcl::Method method, float eta)
{
    ggxcl::SampleParams p = chi_square_conductor(method);
    p.eta = eta;
    return p;
}

} // namespace ggxvk
