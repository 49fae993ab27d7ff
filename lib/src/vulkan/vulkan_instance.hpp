// vulkan_instance.hpp - the process's Vulkan instance, made on first use
// through Vulkan-Hpp's RAII classes from the loader opened at run time
// (vk::raii::Context: no link to libvulkan), and its devices.
#pragma once

#include <memory>

#include <vulkan/vulkan_raii.hpp>

#include "ggxcl/vulkan.hpp"

namespace ggxcl::detail {

struct VulkanInstance {
    vk::raii::Context context;
    vk::raii::Instance instance = nullptr;
    vk::raii::DebugUtilsMessengerEXT messenger = nullptr;  // with GGXCL_VULKAN_VALIDATION=1
};

// The shared instance (Vulkan 1.1); DeviceError when the loader or a driver is missing.
// GGXCL_VULKAN_VALIDATION=1 turns on the Khronos validation layer (vulkan-validationlayers):
// any error or warning it reports is printed and ends the process (abort), as a sanitizer does.
std::shared_ptr<VulkanInstance> vulkan_instance();

// The physical device of list_vulkan_devices()[index].
vk::raii::PhysicalDevice vulkan_physical_device(const VulkanInstance& vulkan, std::size_t index);

} // namespace ggxcl::detail
