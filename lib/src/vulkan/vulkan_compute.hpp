// vulkan_compute.hpp - one Vulkan device as the samplers use it: a compute
// queue, storage buffers in host-visible memory that stay mapped, one
// pipeline layout (two storage buffers, inputs at binding 0 and outputs at
// binding 1 of set 0, and the push constants of ggx_contract.h's
// GGX_BULK_REQUEST_MEMBERS), pipelines made from SPIR-V, and a dispatch
// that waits for its end.  Work-groups beyond the device's count per
// dimension go to a second dimension (dispatch_shape).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

#include "vulkan_instance.hpp"

namespace ggxcl::detail {

// A storage buffer and its memory, mapped for the host while it lives.
struct MappedBuffer {
    vk::raii::Buffer buffer = nullptr;
    vk::raii::DeviceMemory memory = nullptr;
    float* data = nullptr;
    std::uint64_t floats = 0;
};

// A dispatch of `items` invocations in work-groups of `group_size`: groups in
// x up to the device's limit, rows of them in y; invocation (x, y) is item
// y * row_width + x.
struct DispatchShape {
    std::uint32_t groups_x = 1, groups_y = 1, row_width = 0;
};
DispatchShape dispatch_shape(std::uint64_t items, std::uint32_t group_size, std::uint32_t max_groups_x,
                             std::uint32_t max_groups_y);

class VulkanCompute {
public:
    VulkanCompute(std::shared_ptr<VulkanInstance> vulkan, const VulkanDeviceInfo& info);

    const VulkanDeviceInfo& info() const { return info_; }

    MappedBuffer buffer(std::uint64_t floats);
    vk::raii::Pipeline pipeline(const std::vector<std::uint32_t>& spirv);

    // Runs `pipeline` over `shape` with `push` (push_bytes) on buffers `inputs` and `outputs`; waits.
    void dispatch(const vk::raii::Pipeline& pipeline, const void* push, std::uint32_t push_bytes,
                  const MappedBuffer& inputs, const MappedBuffer& outputs, const DispatchShape& shape);

private:
    std::shared_ptr<VulkanInstance> vulkan_;  // outlives the device
    VulkanDeviceInfo info_;
    vk::raii::PhysicalDevice physical_ = nullptr;
    vk::raii::Device device_ = nullptr;
    vk::raii::Queue queue_ = nullptr;
    vk::raii::CommandPool pool_ = nullptr;
    vk::raii::DescriptorSetLayout set_layout_ = nullptr;
    vk::raii::PipelineLayout layout_ = nullptr;
    vk::raii::DescriptorPool descriptor_pool_ = nullptr;
    std::uint32_t memory_type_ = 0;
};

} // namespace ggxcl::detail
