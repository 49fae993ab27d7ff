// vulkan_compute.cpp - VulkanCompute on Vulkan-Hpp's RAII classes.
#include "vulkan_compute.hpp"

#include <algorithm>

#include "ggx_contract.h"
#include "ggxcl/error.hpp"

namespace ggxcl::detail {

namespace {

std::uint32_t compute_family(const vk::raii::PhysicalDevice& device)
{
    const auto families = device.getQueueFamilyProperties();
    for (std::uint32_t k = 0; k < families.size(); ++k)
        if (families[k].queueFlags & vk::QueueFlagBits::eCompute)
            return k;
    throw DeviceError("the Vulkan device has no compute queue");
}

// Host-visible coherent memory, cached where the device has it (read back by the host).
std::uint32_t host_memory_type(const vk::raii::PhysicalDevice& device)
{
    const auto memory = device.getMemoryProperties();
    const auto needed = vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent;
    std::uint32_t found = memory.memoryTypeCount;
    for (std::uint32_t k = 0; k < memory.memoryTypeCount; ++k) {
        const auto flags = memory.memoryTypes[k].propertyFlags;
        if ((flags & needed) != needed)
            continue;
        if (flags & vk::MemoryPropertyFlagBits::eHostCached)
            return k;
        found = std::min(found, k);
    }
    if (found == memory.memoryTypeCount)
        throw DeviceError("the Vulkan device has no host-visible coherent memory");
    return found;
}

// The device: shaderInt64 (the samplers need it), and the small types a user's shader may use,
// each where the device has it (VulkanDeviceInfo).
vk::raii::Device create_device(const vk::raii::PhysicalDevice& physical, const VulkanDeviceInfo& info,
                               const vk::DeviceQueueCreateInfo& queue)
{
    static const char* const float16_int8 = VK_KHR_SHADER_FLOAT16_INT8_EXTENSION_NAME;
    vk::PhysicalDeviceFeatures features;
    features.shaderInt64 = VK_TRUE;
    features.shaderInt16 = info.int16 ? VK_TRUE : VK_FALSE;
    vk::PhysicalDevice16BitStorageFeatures storage;
    storage.storageBuffer16BitAccess = info.storage16 ? VK_TRUE : VK_FALSE;
    vk::PhysicalDeviceShaderFloat16Int8Features small;
    small.shaderFloat16 = info.float16 ? VK_TRUE : VK_FALSE;
    small.shaderInt8 = info.int8 ? VK_TRUE : VK_FALSE;
    const bool extension = info.float16 || info.int8;
    vk::StructureChain<vk::DeviceCreateInfo, vk::PhysicalDeviceFeatures2, vk::PhysicalDevice16BitStorageFeatures,
                       vk::PhysicalDeviceShaderFloat16Int8Features>
        chain(vk::DeviceCreateInfo({}, 1, &queue, 0, nullptr, extension ? 1 : 0, extension ? &float16_int8 : nullptr),
              vk::PhysicalDeviceFeatures2(features), storage, small);
    if (!extension)
        chain.unlink<vk::PhysicalDeviceShaderFloat16Int8Features>();
    return vk::raii::Device(physical, chain.get<vk::DeviceCreateInfo>());
}

} // namespace

DispatchShape dispatch_shape(std::uint64_t items, std::uint32_t group_size, std::uint32_t max_groups_x,
                             std::uint32_t max_groups_y)
{
    const std::uint64_t groups = std::max<std::uint64_t>(1, (items + group_size - 1) / group_size);
    DispatchShape shape;
    shape.groups_x = std::uint32_t(std::min<std::uint64_t>(groups, max_groups_x));
    shape.groups_y = std::uint32_t((groups + shape.groups_x - 1) / shape.groups_x);
    shape.row_width = shape.groups_x * group_size;
    if (shape.groups_y > max_groups_y)
        throw InvalidArgument("samples per dispatch", std::to_string(items),
                              "at most " + std::to_string(std::uint64_t(max_groups_x) * max_groups_y * group_size) +
                                  " on this Vulkan device");
    return shape;
}

VulkanCompute::VulkanCompute(std::shared_ptr<VulkanInstance> vulkan, const VulkanDeviceInfo& info)
    : vulkan_(std::move(vulkan)), info_(info)
{
    if (!info_.int64)
        throw DeviceError("the Vulkan device '" + info_.name +
                          "' lacks shaderInt64, which the samplers' uniforms need (Philox, Sobol)");
    if (info_.max_push_constants < GGX_BULK_REQUEST_WORDS * 4)
        throw DeviceError("the Vulkan device '" + info_.name + "' has " + std::to_string(info_.max_push_constants) +
                          " bytes of push constants; the samplers need " + std::to_string(GGX_BULK_REQUEST_WORDS * 4));
    physical_ = vulkan_physical_device(*vulkan_, info_.index);
    const std::uint32_t family = compute_family(physical_);
    const float priority = 1.0f;
    const vk::DeviceQueueCreateInfo queue_info({}, family, 1, &priority);
    device_ = create_device(physical_, info_, queue_info);
    queue_ = vk::raii::Queue(device_, family, 0);
    pool_ = vk::raii::CommandPool(
        device_, vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer, family));
    const std::array<vk::DescriptorSetLayoutBinding, 2> bindings = {
        vk::DescriptorSetLayoutBinding(0, vk::DescriptorType::eStorageBuffer, 1, vk::ShaderStageFlagBits::eCompute),
        vk::DescriptorSetLayoutBinding(1, vk::DescriptorType::eStorageBuffer, 1, vk::ShaderStageFlagBits::eCompute)};
    set_layout_ = vk::raii::DescriptorSetLayout(device_, vk::DescriptorSetLayoutCreateInfo({}, bindings));
    const vk::PushConstantRange push_range(vk::ShaderStageFlagBits::eCompute, 0, GGX_BULK_REQUEST_WORDS * 4);
    layout_ = vk::raii::PipelineLayout(device_, vk::PipelineLayoutCreateInfo({}, *set_layout_, push_range));
    const vk::DescriptorPoolSize pool_size(vk::DescriptorType::eStorageBuffer, 2);
    descriptor_pool_ = vk::raii::DescriptorPool(
        device_, vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, pool_size));
    memory_type_ = host_memory_type(physical_);
}

MappedBuffer VulkanCompute::buffer(std::uint64_t floats)
{
    MappedBuffer b;
    b.floats = std::max<std::uint64_t>(floats, 1);
    const vk::DeviceSize bytes = b.floats * sizeof(float);
    b.buffer = vk::raii::Buffer(device_, vk::BufferCreateInfo({}, bytes, vk::BufferUsageFlagBits::eStorageBuffer));
    const auto needs = b.buffer.getMemoryRequirements();
    if (!(needs.memoryTypeBits & (1u << memory_type_)))
        throw DeviceError("the Vulkan device '" + info_.name + "' cannot put a storage buffer in host-visible memory");
    b.memory = vk::raii::DeviceMemory(device_, vk::MemoryAllocateInfo(needs.size, memory_type_));
    b.buffer.bindMemory(*b.memory, 0);
    b.data = static_cast<float*>(b.memory.mapMemory(0, bytes));
    return b;
}

vk::raii::Pipeline VulkanCompute::pipeline(const std::vector<std::uint32_t>& spirv)
{
    const vk::raii::ShaderModule module(device_, vk::ShaderModuleCreateInfo({}, spirv));
    const vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute, *module, "main");
    return vk::raii::Pipeline(device_, nullptr, vk::ComputePipelineCreateInfo({}, stage, *layout_));
}

void VulkanCompute::dispatch(const vk::raii::Pipeline& pipeline, const void* push, std::uint32_t push_bytes,
                             const MappedBuffer& inputs, const MappedBuffer& outputs, const DispatchShape& shape)
{
    vk::raii::DescriptorSets sets(device_, vk::DescriptorSetAllocateInfo(*descriptor_pool_, *set_layout_));
    const std::array<vk::DescriptorBufferInfo, 2> infos = {vk::DescriptorBufferInfo(*inputs.buffer, 0, VK_WHOLE_SIZE),
                                                           vk::DescriptorBufferInfo(*outputs.buffer, 0, VK_WHOLE_SIZE)};
    const std::array<vk::WriteDescriptorSet, 2> writes = {
        vk::WriteDescriptorSet(*sets[0], 0, 0, 1, vk::DescriptorType::eStorageBuffer, nullptr, &infos[0]),
        vk::WriteDescriptorSet(*sets[0], 1, 0, 1, vk::DescriptorType::eStorageBuffer, nullptr, &infos[1])};
    device_.updateDescriptorSets(writes, nullptr);

    vk::raii::CommandBuffers commands(device_, vk::CommandBufferAllocateInfo(*pool_, vk::CommandBufferLevel::ePrimary, 1));
    vk::raii::CommandBuffer& command = commands[0];
    command.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    command.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline);
    command.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *layout_, 0, *sets[0], nullptr);
    command.pushConstants<std::uint8_t>(
        *layout_, vk::ShaderStageFlagBits::eCompute, 0,
        vk::ArrayProxy<const std::uint8_t>(push_bytes, static_cast<const std::uint8_t*>(push)));
    command.dispatch(shape.groups_x, shape.groups_y, 1);
    const vk::MemoryBarrier to_host(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eHostRead);
    command.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eHost, {}, to_host,
                            nullptr, nullptr);
    command.end();
    const vk::raii::Fence fence(device_, vk::FenceCreateInfo());
    const vk::CommandBuffer raw = *command;
    queue_.submit(vk::SubmitInfo({}, {}, raw), *fence);
    if (device_.waitForFences(*fence, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
        throw DeviceError("the Vulkan dispatch on '" + info_.name + "' did not finish");
}

} // namespace ggxcl::detail
