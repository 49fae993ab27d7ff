// test_vulkan_histogram.cpp - histograms binned on a Vulkan device
// (VulkanSampler::histogram, kernels/ggx_histogram.comp; lavapipe in CI)
// against OpenCL's, and the device's limit:
//   - the counts equal OpenCL's histogram of the same request but for
//     samples within float rounding of a bin edge (o and m);
//   - more bins than shared memory holds are refused, naming the limit.
// (Every method's fit to its pdf, with its negative controls, is
// test_histogram_fit's, run on OpenCL and on Vulkan in GLSL and in HLSL.)
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "device_fixture.hpp"
#include "vulkan_fixture.hpp"

namespace {

using ggxcl::ShaderLanguage;

ggxcl::VulkanSampler& vulkan(ShaderLanguage language)
{
    return ggxvk::vulkan_sampler(language);
}

ggxcl::SampleParams conductor(ggxcl::Method method)
{
    return ggxvk::chi_square_conductor(method);
}

ggxcl::SampleParams dielectric(ggxcl::Method method, float eta)
{
    return ggxvk::chi_square_dielectric(method, eta);
}

} // namespace

TEST_CASE("the Vulkan histogram counts OpenCL's but for samples at a bin edge")
{
    for (const ggxcl::Field direction : {ggxcl::Field::o, ggxcl::Field::m})
        for (const ggxcl::SampleParams& p : {conductor(ggxcl::Method::bounded), dielectric(ggxcl::Method::heitz, 1.33f)}) {
            const ggxcl::SampleRange range{42, 1000, 300000};
            const ggxcl::Histogram v = vulkan(ShaderLanguage::glsl).histogram(p, range, 16, 32, direction);
            const ggxcl::Histogram c = ggxtest::sampler().histogram(p, range, 16, 32, direction);
            std::uint64_t moved = 0;
            for (std::size_t b = 0; b < v.counts.size(); ++b)
                moved += v.counts[b] > c.counts[b] ? v.counts[b] - c.counts[b] : c.counts[b] - v.counts[b];
            MESSAGE(ggxcl::method_name(p.method) << (p.eta != 0.0f ? " dielectric " : " ") << ggxcl::field_name(direction)
                                                 << ": " << moved << " of " << range.count << " samples in another bin");
            CHECK(v.total() == c.total());
            CHECK(moved <= 30);  // 1e-4 of the samples
            CHECK(v.invalid == c.invalid);
        }
}

TEST_CASE("a histogram larger than the device's shared memory is refused, naming the limit")
{
    const std::uint32_t shared = vulkan(ShaderLanguage::glsl).device().max_shared_memory;
    const int bins_phi = 64, bins_z = int(shared / 4 / 64) + 1;
    CHECK_THROWS_WITH_AS(vulkan(ShaderLanguage::glsl).histogram(conductor(ggxcl::Method::caps), {1, 0, 100}, bins_z, bins_phi),
                         doctest::Contains("local memory"), ggxcl::InvalidArgument);
}
