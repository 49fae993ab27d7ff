// spirv_features.hpp - the device features a SPIR-V module's capabilities
// need (the 16- and 8-bit types a user's shader may use), checked against
// what the Vulkan device has, so that a shader the device cannot run is a
// BuildError naming the feature, not a validation error or a crash.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ggxcl/vulkan.hpp"

namespace ggxcl::detail {

// The first capability of `spirv` whose device feature `device` lacks, as "SPIR-V capability
// Float16 needs shaderFloat16"; empty when the device has every one it declares.
std::string missing_device_feature(const std::vector<std::uint32_t>& spirv, const VulkanDeviceInfo& device);

} // namespace ggxcl::detail
