// compute_device.cpp - ComputeDevice on Vulkan-Hpp's RAII classes.
#include "compute_device.hpp"

#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>

#include <vulkan/vulkan_raii.hpp>

#include "vulkan/vulkan_instance.hpp"  // lib/src

namespace ggxvk {

struct ComputeDevice::State {
    std::shared_ptr<ggxcl::detail::VulkanInstance> vulkan;  // the runtime's: GGXCL_VULKAN_VALIDATION applies
    vk::raii::PhysicalDevice physical = nullptr;
    vk::raii::Device device = nullptr;
    vk::raii::Queue queue = nullptr;
    vk::raii::CommandPool pool = nullptr;
    std::uint32_t family = 0;
};

namespace {

vk::raii::PhysicalDevice pick_device(const vk::raii::Instance& instance)
{
    vk::raii::PhysicalDevices devices(instance);
    if (devices.empty())
        throw std::runtime_error("no Vulkan device (install mesa-vulkan-drivers for lavapipe)");
    const char* wanted = std::getenv("GGXCL_VULKAN_DEVICE");
    for (const vk::raii::PhysicalDevice& device : devices) {
        const auto properties = device.getProperties();
        const std::string name = properties.deviceName.data();
        if (wanted ? name.find(wanted) != std::string::npos : properties.deviceType == vk::PhysicalDeviceType::eCpu)
            return device;
    }
    if (wanted)
        throw std::runtime_error(std::string("no Vulkan device named like GGXCL_VULKAN_DEVICE=") + wanted);
    return std::move(devices.front());
}

std::uint32_t compute_family(const vk::raii::PhysicalDevice& device)
{
    const auto families = device.getQueueFamilyProperties();
    for (std::uint32_t k = 0; k < families.size(); ++k)
        if (families[k].queueFlags & vk::QueueFlagBits::eCompute)
            return k;
    throw std::runtime_error("the Vulkan device has no compute queue");
}

std::uint32_t host_visible_type(const vk::raii::PhysicalDevice& device, std::uint32_t allowed)
{
    const auto memory = device.getMemoryProperties();
    const auto wanted = vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent;
    for (std::uint32_t k = 0; k < memory.memoryTypeCount; ++k)
        if ((allowed & (1u << k)) && (memory.memoryTypes[k].propertyFlags & wanted) == wanted)
            return k;
    throw std::runtime_error("the Vulkan device has no host-visible coherent memory");
}

// A storage buffer in host-visible memory holding a copy of `array`.
struct DeviceArray {
    vk::raii::Buffer buffer = nullptr;
    vk::raii::DeviceMemory memory = nullptr;
};

DeviceArray upload(const ComputeDevice::State& s, const HostArray& array)
{
    DeviceArray out;
    const vk::DeviceSize bytes = array.bytes ? array.bytes : 4;
    out.buffer = vk::raii::Buffer(s.device, vk::BufferCreateInfo({}, bytes, vk::BufferUsageFlagBits::eStorageBuffer));
    const auto needs = out.buffer.getMemoryRequirements();
    out.memory = vk::raii::DeviceMemory(
        s.device, vk::MemoryAllocateInfo(needs.size, host_visible_type(s.physical, needs.memoryTypeBits)));
    out.buffer.bindMemory(*out.memory, 0);
    void* mapped = out.memory.mapMemory(0, bytes);
    std::memcpy(mapped, array.data, array.bytes);
    out.memory.unmapMemory();
    return out;
}

} // namespace

ComputeDevice::ComputeDevice() : state_(std::make_unique<State>())
{
    State& s = *state_;
    s.vulkan = ggxcl::detail::vulkan_instance();
    s.physical = pick_device(s.vulkan->instance);
    if (!s.physical.getFeatures().shaderInt64)
        throw std::runtime_error(name() + " lacks shaderInt64 (the 64-bit integers of ggx_philox.h and ggx_sobol.h)");
    s.family = compute_family(s.physical);
    const float priority = 1.0f;
    const vk::DeviceQueueCreateInfo queue_info({}, s.family, 1, &priority);
    vk::PhysicalDeviceFeatures features;
    features.shaderInt64 = VK_TRUE;
    s.device = vk::raii::Device(s.physical, vk::DeviceCreateInfo({}, queue_info, {}, {}, &features));
    s.queue = vk::raii::Queue(s.device, s.family, 0);
    s.pool = vk::raii::CommandPool(s.device, vk::CommandPoolCreateInfo({}, s.family));
}

ComputeDevice::~ComputeDevice() = default;

std::string ComputeDevice::name() const
{
    return state_->physical.getProperties().deviceName.data();
}

void ComputeDevice::run(const std::vector<std::uint32_t>& spirv, const void* push, std::uint32_t push_bytes,
                        const std::vector<HostArray>& arrays, std::uint32_t groups)
{
    const State& s = *state_;
    std::vector<DeviceArray> buffers;
    std::vector<vk::DescriptorSetLayoutBinding> bindings;
    for (std::uint32_t k = 0; k < arrays.size(); ++k) {
        buffers.push_back(upload(s, arrays[k]));
        bindings.emplace_back(k, vk::DescriptorType::eStorageBuffer, 1, vk::ShaderStageFlagBits::eCompute);
    }
    const vk::raii::DescriptorSetLayout set_layout(s.device, vk::DescriptorSetLayoutCreateInfo({}, bindings));
    const vk::PushConstantRange push_range(vk::ShaderStageFlagBits::eCompute, 0, push_bytes);
    vk::PipelineLayoutCreateInfo layout_info({}, *set_layout);
    layout_info.setPushConstantRangeCount(push_bytes ? 1 : 0).setPPushConstantRanges(&push_range);
    const vk::raii::PipelineLayout layout(s.device, layout_info);
    const vk::raii::ShaderModule module(s.device, vk::ShaderModuleCreateInfo({}, spirv));
    const vk::raii::Pipeline pipeline(
        s.device, nullptr,
        vk::ComputePipelineCreateInfo({}, vk::PipelineShaderStageCreateInfo({}, vk::ShaderStageFlagBits::eCompute, *module, "main"),
                                      *layout));
    const vk::DescriptorPoolSize pool_size(vk::DescriptorType::eStorageBuffer, std::uint32_t(arrays.size()));
    const vk::raii::DescriptorPool pool(
        s.device, vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, pool_size));
    vk::raii::DescriptorSets sets(s.device, vk::DescriptorSetAllocateInfo(*pool, *set_layout));
    std::vector<vk::DescriptorBufferInfo> infos;
    for (const DeviceArray& b : buffers)
        infos.emplace_back(*b.buffer, 0, VK_WHOLE_SIZE);
    std::vector<vk::WriteDescriptorSet> writes;
    for (std::uint32_t k = 0; k < infos.size(); ++k)
        writes.emplace_back(*sets[0], k, 0, 1, vk::DescriptorType::eStorageBuffer, nullptr, &infos[k]);
    s.device.updateDescriptorSets(writes, nullptr);

    vk::raii::CommandBuffers commands(s.device, vk::CommandBufferAllocateInfo(*s.pool, vk::CommandBufferLevel::ePrimary, 1));
    vk::raii::CommandBuffer& command = commands[0];
    command.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    command.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline);
    command.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *layout, 0, *sets[0], nullptr);
    if (push_bytes)
        command.pushConstants<std::uint8_t>(*layout, vk::ShaderStageFlagBits::eCompute, 0,
                                            vk::ArrayProxy<const std::uint8_t>(push_bytes, static_cast<const std::uint8_t*>(push)));
    command.dispatch(groups, 1, 1);
    const vk::MemoryBarrier to_host(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eHostRead);
    command.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eHost, {}, to_host,
                            nullptr, nullptr);
    command.end();
    const vk::raii::Fence fence(s.device, vk::FenceCreateInfo());
    const vk::CommandBuffer raw = *command;
    s.queue.submit(vk::SubmitInfo({}, {}, raw), *fence);
    if (s.device.waitForFences(*fence, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
        throw std::runtime_error("the Vulkan dispatch did not finish");
    for (std::size_t k = 0; k < arrays.size(); ++k) {
        const void* mapped = buffers[k].memory.mapMemory(0, arrays[k].bytes ? arrays[k].bytes : 4);
        std::memcpy(arrays[k].data, mapped, arrays[k].bytes);
        buffers[k].memory.unmapMemory();
    }
}

} // namespace ggxvk
