// validation_probe.cpp - the negative control of the Vulkan validation run:
// a dispatch through the runtime's VulkanCompute whose push constants
// overrun the pipeline layout's range (VUID-vkCmdPushConstants-offset-01796),
// which GGXCL_VULKAN_VALIDATION=1 must report and stop.  Exits 0 only when
// nothing stopped it.
#include <cstdio>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "vulkan/spirv_compile.hpp"  // lib/src: the runtime's own
#include "vulkan/vulkan_compute.hpp"

int main()
{
    const ggxcl::VulkanDeviceInfo info = ggxcl::select_vulkan_device();
    ggxcl::detail::VulkanCompute compute(ggxcl::detail::vulkan_instance(), info);
    const auto shader = ggxcl::detail::compile_shader(ggxcl::ShaderLanguage::glsl, "ggx_bulk.comp",
                                                      {{"GGX_METHOD", 0}, {"GGX_WRITE_MASK", 2}});
    const auto pipeline = compute.pipeline(shader.spirv);
    const auto inputs = compute.buffer(4), outputs = compute.buffer(64);
    std::vector<unsigned char> push(256, 0);  // the layout has 104 bytes
    compute.dispatch(pipeline, push.data(), std::uint32_t(push.size()), inputs, outputs, {1, 1, 64});
    std::puts("validation_probe: the overrun went unreported");
    return 0;
}
