// vulkan_fixture.hpp - what the Vulkan suites share: one VulkanSampler per
// shading language on the default Vulkan device, and the requests the
// chi-square suites draw (a conductor, anisotropic where the method allows,
// and the same surface as a dielectric).
#pragma once

#include <ggxcl/ggxcl.hpp>

#include "shader_compiler.hpp"  // all_shader_languages

namespace ggxvk {

// The runtime's sampler for `language` (made once, destroyed at exit).
ggxcl::VulkanSampler& vulkan_sampler(ggxcl::ShaderLanguage language);

// alpha (0.35, 0.7) (0.35 where the method is isotropic), view (0.6, 0.3, 0.5) normalized.
ggxcl::SampleParams chi_square_conductor(ggxcl::Method method);
// The same surface as a dielectric of relative index eta.
ggxcl::SampleParams chi_square_dielectric(ggxcl::Method method, float eta);

} // namespace ggxvk
