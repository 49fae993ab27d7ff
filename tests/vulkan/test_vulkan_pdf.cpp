// test_vulkan_pdf.cpp - the pdf and the BSDF value of given directions on a
// Vulkan device (VulkanSampler::pdf and eval, kernels/ggx_pdf.comp and
// .hlsl; lavapipe in CI), in GLSL and HLSL:
//   - every method's pdf and eval of 4096 directions (over the whole
//     sphere, and OpenCL's own samples), conductor and dielectric, agree
//     with OpenCL's Sampler::pdf and eval: 99% within 1e-4 relative, all
//     within 1e-2 relative (or 1e-6 absolute, near zero);
//   - the same with a view per sample;
//   (the chunk size's independence and the refusal of no directions are
//   test_pdf_consistency's, run on both back ends;)
//   - negative control: ndf's pdf is not heitz's, and the check sees it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "device_fixture.hpp"
#include "vulkan_fixture.hpp"

namespace {

using ggxcl::ShaderLanguage;

// Half over the sphere, half the samples OpenCL draws for p (where the pdf is large).
std::vector<ggxcl::Vec3> directions_for(const ggxcl::SampleParams& p)
{
    std::vector<ggxcl::Vec3> dirs;
    std::mt19937 rng(7);
    std::normal_distribution<float> gauss;
    for (int k = 0; k < 2048; ++k)
        dirs.push_back(ggxcl::unit_vector({gauss(rng), gauss(rng), gauss(rng)}));
    const ggxcl::SampleSet s = ggxtest::sampler().generate(p, {3, 0, 2048}, {ggxcl::Field::o});
    for (std::uint64_t j = 0; j < s.count; ++j)
        dirs.push_back({s.o[j], s.o[s.count + j], s.o[2 * s.count + j]});
    return dirs;
}

// The fraction of values within 1e-4 relative of OpenCL's, and whether all are within 1e-2 (or 1e-6).
struct Agreement {
    double close = 0;
    bool all_near = true;
};

Agreement agreement(const std::vector<float>& vulkan, const std::vector<float>& opencl)
{
    REQUIRE(vulkan.size() == opencl.size());
    Agreement a;
    for (std::size_t j = 0; j < vulkan.size(); ++j) {
        const double d = std::fabs(double(vulkan[j]) - opencl[j]), scale = std::fabs(double(opencl[j]));
        a.close += d <= 1e-4 * scale + 1e-7 ? 1 : 0;
        a.all_near = a.all_near && std::isfinite(vulkan[j]) && d <= 1e-2 * scale + 1e-6;
    }
    a.close /= double(vulkan.size());
    return a;
}

void check_agreement(const std::vector<float>& vulkan, const std::vector<float>& opencl, const char* what)
{
    const Agreement a = agreement(vulkan, opencl);
    INFO(what << ": " << a.close << " within 1e-4");
    CHECK(a.close >= 0.99);
    CHECK(a.all_near);
}

void check_method(ShaderLanguage language, const ggxcl::SampleParams& p)
{
    const std::vector<ggxcl::Vec3> dirs = directions_for(p);
    ggxcl::VulkanSampler& vk = ggxvk::vulkan_sampler(language);
    check_agreement(vk.pdf(p, dirs), ggxtest::sampler().pdf(p, dirs), "pdf");
    check_agreement(vk.eval(p, dirs), ggxtest::sampler().eval(p, dirs), "eval");
}

} // namespace

TEST_CASE("every method's pdf and eval on Vulkan agree with OpenCL's, conductor and dielectric")
{
    for (ShaderLanguage language : ggxvk::all_shader_languages)
        for (ggxcl::Method method : ggxcl::all_methods) {
            CAPTURE(std::string(ggxcl::shader_language_name(language)));
            CAPTURE(ggxcl::method_name(method));
            check_method(language, ggxvk::chi_square_conductor(method));
            if (ggxcl::method_traits(method).dielectric)
                check_method(language, ggxvk::chi_square_dielectric(method, 1.5f));
        }
}

TEST_CASE("pdf with a view per sample agrees with OpenCL's")
{
    for (ShaderLanguage language : ggxvk::all_shader_languages) {
        CAPTURE(std::string(ggxcl::shader_language_name(language)));
        ggxcl::VulkanSampler& vk = ggxvk::vulkan_sampler(language);
        const ggxcl::SampleParams p = ggxvk::chi_square_conductor(ggxcl::Method::bounded);
        const std::vector<ggxcl::Vec3> dirs = directions_for(p);
        ggxcl::PerSampleInputs views;
        for (std::size_t j = 0; j < dirs.size(); ++j)
            views.views.push_back(ggxcl::unit_vector({0.1f * float(j % 7), -0.2f, 1.0f}));
        check_agreement(vk.pdf(p, dirs, views), ggxtest::sampler().pdf(p, dirs, views), "pdf, views per sample");
    }
}

TEST_CASE("negative control: ndf's pdf on Vulkan is not heitz's on OpenCL")
{
    const ggxcl::SampleParams ndf = ggxvk::chi_square_conductor(ggxcl::Method::ndf);
    ggxcl::SampleParams heitz = ndf;
    heitz.method = ggxcl::Method::heitz;
    const std::vector<ggxcl::Vec3> dirs = directions_for(ndf);
    const Agreement a = agreement(ggxvk::vulkan_sampler(ShaderLanguage::glsl).pdf(ndf, dirs),
                                  ggxtest::sampler().pdf(heitz, dirs));
    CHECK(a.close < 0.99);
    CHECK(!a.all_near);
}
