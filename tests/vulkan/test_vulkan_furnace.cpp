// test_vulkan_furnace.cpp - the fused white-furnace estimator on a Vulkan
// device (VulkanSampler::furnace, kernels/ggx_furnace.comp and .hlsl;
// lavapipe in CI), in GLSL and HLSL:
//   - every method's sums, conductor and dielectric, agree with OpenCL's
//     furnace of the same request (the same samples, float rounding apart):
//     the albedo, its per-sample variance and a dielectric's reflectance;
//   (that the sums do not depend on the chunk size is test_furnace's, run on
//   both back ends;)
//   - negative control: another seed moves the sums by more than the tolerance.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "device_fixture.hpp"
#include "vulkan_fixture.hpp"

namespace {

using ggxcl::ShaderLanguage;

constexpr std::uint64_t samples = 200003;  // not a multiple of the samples per invocation
constexpr double tolerance = 2e-5;  // relative: float weights summed per invocation, then in double

void check_close(double vulkan, double opencl, const char* what)
{
    INFO(what << ": Vulkan " << vulkan << ", OpenCL " << opencl);
    CHECK(std::fabs(vulkan - opencl) <= tolerance * std::fabs(opencl) + 1e-12);
}

void check_against_opencl(ShaderLanguage language, const ggxcl::SampleParams& p)
{
    const ggxcl::SampleRange range{11, 5, samples};
    const ggxcl::FurnaceSums vk = ggxvk::vulkan_sampler(language).furnace(p, range);
    const ggxcl::FurnaceSums cl = ggxtest::sampler().furnace(p, range);
    CHECK(vk.count == samples);
    check_close(vk.mean(), cl.mean(), "albedo");
    check_close(vk.sum_of_squares, cl.sum_of_squares, "sum of squares");
    check_close(vk.reflected_sum, cl.reflected_sum, "reflected sum");
    CHECK(vk.mean() > 0.3);  // energy kept: 0.64 for the conductor, 0.42 for the dielectric in radiance
    CHECK(vk.mean() <= 1.0);
}

} // namespace

TEST_CASE("every method's furnace on Vulkan agrees with OpenCL's, conductor and dielectric")
{
    for (ShaderLanguage language : ggxvk::all_shader_languages)
        for (ggxcl::Method method : ggxcl::all_methods) {
            CAPTURE(std::string(ggxcl::shader_language_name(language)));
            CAPTURE(ggxcl::method_name(method));
            check_against_opencl(language, ggxvk::chi_square_conductor(method));
            if (ggxcl::method_traits(method).dielectric)
                check_against_opencl(language, ggxvk::chi_square_dielectric(method, 1.5f));
        }
}

TEST_CASE("negative control: another seed moves the furnace's sums past the tolerance")
{
    const ggxcl::SampleParams p = ggxvk::chi_square_conductor(ggxcl::Method::heitz);
    ggxcl::VulkanSampler& vk = ggxvk::vulkan_sampler(ShaderLanguage::glsl);
    const ggxcl::FurnaceSums a = vk.furnace(p, {11, 5, samples}), b = vk.furnace(p, {12, 5, samples});
    CHECK(std::fabs(a.sum_of_squares - b.sum_of_squares) > tolerance * std::fabs(a.sum_of_squares));
}
