// spirv_features.cpp - OpCapability instructions read from a SPIR-V module's words.
#include "spirv_features.hpp"

namespace ggxcl::detail {

namespace {

constexpr std::uint32_t op_capability = 17;  // SPIR-V specification, 3.42.15 (opcode) and 3.31 (capabilities)
constexpr std::size_t header_words = 5;

struct CapabilityNeed {
    std::uint32_t capability;
    const char* name;
    const char* feature;
    bool VulkanDeviceInfo::*has;
};

const CapabilityNeed needs[] = {
    {9, "Float16", "shaderFloat16", &VulkanDeviceInfo::float16},
    {22, "Int16", "shaderInt16", &VulkanDeviceInfo::int16},
    {39, "Int8", "shaderInt8", &VulkanDeviceInfo::int8},
    {4433, "StorageBuffer16BitAccess", "storageBuffer16BitAccess", &VulkanDeviceInfo::storage16},
};

} // namespace

std::string missing_device_feature(const std::vector<std::uint32_t>& spirv, const VulkanDeviceInfo& device)
{
    for (std::size_t at = header_words; at < spirv.size();) {
        const std::uint32_t words = spirv[at] >> 16, opcode = spirv[at] & 0xffffu;
        if (words == 0)
            break;
        if (opcode == op_capability && at + 1 < spirv.size())
            for (const CapabilityNeed& need : needs)
                if (spirv[at + 1] == need.capability && !(device.*need.has))
                    return std::string("SPIR-V capability ") + need.name + " needs " + need.feature +
                           ", which the Vulkan device '" + device.name + "' lacks";
        at += words;
    }
    return "";
}

} // namespace ggxcl::detail
