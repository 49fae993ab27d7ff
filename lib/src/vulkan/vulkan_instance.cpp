// vulkan_instance.cpp - the Vulkan instance, device listing and selection
// (index or name part, explicit or from GGXCL_VULKAN_DEVICE).
#include "vulkan_instance.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <mutex>

#include "ggxcl/error.hpp"

namespace ggxcl {

namespace detail {

namespace {

const char* install_hint = "install the Vulkan loader and a driver, e.g. on Debian: apt-get install libvulkan1 "
                           "mesa-vulkan-drivers (lavapipe, on the CPU)";

bool validation_wanted()
{
    const char* value = std::getenv("GGXCL_VULKAN_VALIDATION");
    return value && std::string(value) == "1";
}

VKAPI_ATTR VkBool32 VKAPI_CALL report_validation(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                 void*)
{
    const bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    std::fprintf(stderr, "ggxcl: Vulkan validation %s: %s\n", error ? "error" : "warning",
                 data && data->pMessage ? data->pMessage : "(no message)");
    std::abort();
}

std::shared_ptr<VulkanInstance> make_instance()
{
    auto vulkan = std::make_shared<VulkanInstance>();
    const vk::ApplicationInfo app("ggxcl", 1, "ggxcl", 1, VK_API_VERSION_1_1);
    const bool validate = validation_wanted();
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    vk::InstanceCreateInfo info({}, &app);
    if (validate)
        info.setPEnabledLayerNames(layer).setPEnabledExtensionNames(extension);
    try {
        vulkan->instance = vk::raii::Instance(vulkan->context, info);
    } catch (const vk::LayerNotPresentError&) {
        throw DeviceError("GGXCL_VULKAN_VALIDATION=1 needs the Khronos validation layer; on Debian: apt-get install "
                          "vulkan-validationlayers");
    } catch (const vk::SystemError& e) {
        throw DeviceError(std::string("no Vulkan instance (") + e.what() + "); " + install_hint);
    }
    if (validate) {
        using Severity = vk::DebugUtilsMessageSeverityFlagBitsEXT;
        using Type = vk::DebugUtilsMessageTypeFlagBitsEXT;
        vulkan->messenger = vk::raii::DebugUtilsMessengerEXT(
            vulkan->instance, vk::DebugUtilsMessengerCreateInfoEXT({}, Severity::eWarning | Severity::eError,
                                                                   Type::eGeneral | Type::eValidation | Type::ePerformance,
                                                                   &report_validation));
    }
    return vulkan;
}

std::string device_type_name(vk::PhysicalDeviceType type)
{
    switch (type) {
    case vk::PhysicalDeviceType::eDiscreteGpu: return "GPU";
    case vk::PhysicalDeviceType::eIntegratedGpu: return "integrated GPU";
    case vk::PhysicalDeviceType::eVirtualGpu: return "virtual GPU";
    case vk::PhysicalDeviceType::eCpu: return "CPU";
    default: return "other";
    }
}

std::string version_text(std::uint32_t v)
{
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
           std::to_string(VK_API_VERSION_PATCH(v));
}

// The 16- and 8-bit types a device offers a shader (vulkan_compute.cpp enables them).
void read_small_types(const vk::raii::PhysicalDevice& device, VulkanDeviceInfo& info)
{
    info.int16 = device.getFeatures().shaderInt16 == VK_TRUE;
    bool has_float16_int8 = false;
    for (const vk::ExtensionProperties& e : device.enumerateDeviceExtensionProperties())
        has_float16_int8 = has_float16_int8 || std::string(e.extensionName.data()) == VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME;
    if (has_float16_int8) {
        const auto chain = device.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDevice16BitStorageFeatures,
                                               vk::PhysicalDeviceShaderFloat16Int8Features>();
        info.float16 = chain.get<vk::PhysicalDeviceShaderFloat16Int8Features>().shaderFloat16 == VK_TRUE;
        info.int8 = chain.get<vk::PhysicalDeviceShaderFloat16Int8Features>().shaderInt8 == VK_TRUE;
        info.storage16 = chain.get<vk::PhysicalDevice16BitStorageFeatures>().storageBuffer16BitAccess == VK_TRUE;
    } else {
        const auto chain = device.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDevice16BitStorageFeatures>();
        info.storage16 = chain.get<vk::PhysicalDevice16BitStorageFeatures>().storageBuffer16BitAccess == VK_TRUE;
    }
}

VulkanDeviceInfo describe(const vk::raii::PhysicalDevice& device, std::size_t index)
{
    const auto properties = device.getProperties();
    const vk::PhysicalDeviceLimits& limits = properties.limits;
    VulkanDeviceInfo info;
    info.index = index;
    info.name = properties.deviceName.data();
    info.type = device_type_name(properties.deviceType);
    info.api_version = version_text(properties.apiVersion);
    info.driver = "driver " + std::to_string(properties.driverVersion);
    info.max_storage_buffer_range = limits.maxStorageBufferRange;
    info.max_work_groups_x = limits.maxComputeWorkGroupCount[0];
    info.max_work_groups_y = limits.maxComputeWorkGroupCount[1];
    info.max_push_constants = limits.maxPushConstantsSize;
    info.max_shared_memory = limits.maxComputeSharedMemorySize;
    info.int64 = device.getFeatures().shaderInt64 == VK_TRUE;
    read_small_types(device, info);
    return info;
}

std::string lowercase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

} // namespace

std::shared_ptr<VulkanInstance> vulkan_instance()
{
    // Never destroyed: the loader (dlopen'ed by vk::raii::Context) stays loaded to the end, so a
    // sampler destroyed by another static's destructor still finds its instance, and LeakSanitizer
    // can name the driver's frames.
    static std::mutex mutex;
    static std::shared_ptr<VulkanInstance>& shared = *new std::shared_ptr<VulkanInstance>;
    std::lock_guard<std::mutex> lock(mutex);
    if (!shared) {
        try {
            shared = make_instance();
        } catch (const DeviceError&) {
            throw;
        } catch (const std::exception& e) {  // vk::raii::Context: "Failed to load vulkan library!"
            throw DeviceError(std::string("no Vulkan loader (libvulkan.so.1: ") + e.what() + "); " + install_hint);
        }
    }
    return shared;
}

vk::raii::PhysicalDevice vulkan_physical_device(const VulkanInstance& vulkan, std::size_t index)
{
    vk::raii::PhysicalDevices devices(vulkan.instance);
    return std::move(devices.at(index));
}

} // namespace detail

bool vulkan_built() { return true; }

std::vector<VulkanDeviceInfo> list_vulkan_devices()
{
    std::shared_ptr<detail::VulkanInstance> vulkan = detail::vulkan_instance();
    std::vector<VulkanDeviceInfo> devices;
    try {
        vk::raii::PhysicalDevices found(vulkan->instance);
        for (const vk::raii::PhysicalDevice& device : found)
            devices.push_back(detail::describe(device, devices.size()));
    } catch (const vk::SystemError&) {
        devices.clear();  // no driver: vkEnumeratePhysicalDevices fails with VK_ERROR_INITIALIZATION_FAILED
    }
    if (devices.empty())
        throw DeviceError(std::string("the Vulkan loader found no device; ") + detail::install_hint);
    return devices;
}

VulkanDeviceInfo select_vulkan_device(const std::string& selector)
{
    std::string wanted = selector, source = "selector";
    if (wanted.empty()) {
        const char* env = std::getenv("GGXCL_VULKAN_DEVICE");
        wanted = env ? env : "";
        source = "GGXCL_VULKAN_DEVICE";
    }
    const std::vector<VulkanDeviceInfo> devices = list_vulkan_devices();
    if (wanted.empty())
        return devices.front();
    const bool is_index = std::all_of(wanted.begin(), wanted.end(), [](unsigned char c) { return std::isdigit(c); });
    for (const VulkanDeviceInfo& d : devices)
        if (is_index ? std::to_string(d.index) == wanted
                     : detail::lowercase(d.name).find(detail::lowercase(wanted)) != std::string::npos)
            return d;
    std::string names;
    for (const VulkanDeviceInfo& d : devices)
        names += (names.empty() ? " " : "; ") + std::to_string(d.index) + ": " + d.name + " (" + d.type + ")";
    throw NoMatchingDevice("no Vulkan device matches " + source + " '" + wanted +
                           "'; give an index or part of a name from:" + names);
}

} // namespace ggxcl
