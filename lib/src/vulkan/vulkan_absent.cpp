// vulkan_absent.cpp - the Vulkan API of a build without the back end
// (Vulkan-Hpp or shaderc not found): every entry point says so.
#include "backend_factories.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/vulkan.hpp"

namespace ggxcl {

namespace {
[[noreturn]] void not_built()
{
    throw DeviceError("this ggxcl was built without Vulkan; install libvulkan-dev and libshaderc-dev "
                      "(with glslang-dev) and build it again");
}
} // namespace

struct VulkanSampler::State {};

namespace detail {
std::unique_ptr<Backend> open_vulkan_backend(const std::string&, ShaderLanguage) { not_built(); }
} // namespace detail

bool vulkan_built() { return false; }
std::vector<VulkanDeviceInfo> list_vulkan_devices() { not_built(); }
VulkanDeviceInfo select_vulkan_device(const std::string&) { not_built(); }
VulkanSampler::VulkanSampler(const std::string&, ShaderLanguage) { not_built(); }
VulkanSampler::~VulkanSampler() = default;
VulkanSampler::VulkanSampler(VulkanSampler&&) noexcept = default;
VulkanSampler& VulkanSampler::operator=(VulkanSampler&&) noexcept = default;
const VulkanDeviceInfo& VulkanSampler::device() const { not_built(); }
std::string VulkanSampler::device_name() const { not_built(); }
ShaderLanguage VulkanSampler::language() const { not_built(); }
void VulkanSampler::set_chunk_size(std::uint64_t) { not_built(); }
std::uint64_t VulkanSampler::chunk_size() const { not_built(); }
std::size_t VulkanSampler::work_group_size() const { not_built(); }
SampleSet VulkanSampler::generate(const SampleParams&, const SampleRange&, FieldSet, const PerSampleInputs&)
{
    not_built();
}
void VulkanSampler::generate_chunks(const SampleParams&, const SampleRange&, FieldSet, const ChunkSink&,
                                    const PerSampleInputs&)
{
    not_built();
}
void VulkanSampler::generate_chunk_views(const SampleParams&, const SampleRange&, FieldSet, const ChunkViewSink&,
                                         const PerSampleInputs&)
{
    not_built();
}
std::vector<float> VulkanSampler::pdf(const SampleParams&, const std::vector<Vec3>&, const PerSampleInputs&)
{
    not_built();
}
std::vector<float> VulkanSampler::eval(const SampleParams&, const std::vector<Vec3>&, const PerSampleInputs&)
{
    not_built();
}
std::vector<float> VulkanSampler::of_directions(const SampleParams&, const std::vector<Vec3>&,
                                                const PerSampleInputs&, bool)
{
    not_built();
}
Histogram VulkanSampler::histogram(const SampleParams&, const SampleRange&, int, int, Field) { not_built(); }
FurnaceSums VulkanSampler::furnace(const SampleParams&, const SampleRange&) { not_built(); }
std::vector<float> VulkanSampler::stress(const StressRequest&, const std::vector<float>&, std::uint32_t)
{
    not_built();
}
std::size_t VulkanSampler::shaders_built() const { not_built(); }
std::size_t VulkanSampler::shaders_from_disk() const { not_built(); }

} // namespace ggxcl
