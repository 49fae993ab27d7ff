// compute_device.hpp - the least Vulkan (through Vulkan-Hpp's RAII classes)
// that runs a compute shader on host arrays: one device with a compute
// queue, storage buffers in host-visible memory bound as bindings 0, 1, ...
// of set 0, the request as push constants, one dispatch, wait, read back.
// The device, of the runtime's Vulkan instance: the first whose name contains
// GGXCL_VULKAN_DEVICE, by default the first CPU device (Mesa's lavapipe), else
// the first device.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ggxvk {

// A host array a shader reads and writes: copied in before, back after.
struct HostArray {
    void* data = nullptr;
    std::size_t bytes = 0;
};
template <typename T>
HostArray host_array(std::vector<T>& values)
{
    return {values.data(), values.size() * sizeof(T)};
}

class ComputeDevice {
public:
    // Throws std::runtime_error naming what is missing (no loader, no device,
    // no device with shaderInt64).
    ComputeDevice();
    ~ComputeDevice();
    ComputeDevice(const ComputeDevice&) = delete;
    ComputeDevice& operator=(const ComputeDevice&) = delete;

    std::string name() const;

    // Runs `spirv` (entry point main) over `groups` work-groups in x.
    void run(const std::vector<std::uint32_t>& spirv, const void* push, std::uint32_t push_bytes,
             const std::vector<HostArray>& arrays, std::uint32_t groups);

    struct State;  // the Vulkan objects (compute_device.cpp)

private:
    std::unique_ptr<State> state_;
};

} // namespace ggxvk
