// vulkan_fixture.hpp - what the Vulkan suites share: one VulkanSampler per
// shading language on the default Vulkan device, and the requests the
// chi-square suites draw (a conductor, anisotropic where the method allows,
// and the same surface as a dielectric).
#pragma once

#include <ggxcl/ggxcl.hpp>

#include "distribution_check.hpp"
#include "shader_compiler.hpp"  // all_shader_languages

namespace ggxvk {

// The runtime's sampler for `language` (made once, destroyed at exit).
ggxcl::VulkanSampler& vulkan_sampler(ggxcl::ShaderLanguage language);

// The chi-square suites' requests (distribution_check.hpp).
using ggxtest::chi_square_conductor;
using ggxtest::chi_square_dielectric;

} // namespace ggxvk
