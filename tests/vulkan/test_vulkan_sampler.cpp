// test_vulkan_sampler.cpp - the runtime's Vulkan back end (ggxcl::VulkanSampler,
// lib/src/vulkan/) on a Vulkan device (Mesa's lavapipe in CI) against the
// OpenCL device (PoCL), in GLSL and in HLSL:
//   - every method's samples of the same request and range (the same seed,
//     so the same Philox uniforms) agree with OpenCL's, conductor and
//     dielectric: m and o 99% <= 1e-5 rad and max <= 2e-3, pdf_o relative
//     99% <= 1e-4, no NaN or Inf; the uniforms (field u) are equal bit for bit;
//   - so do world space, the Sobol sequence and per-sample views, roughness,
//     normals and uniforms;
//   (chunks and shards bit-identical to one call, and the refusal of bad
//   requests, are test_backend_contract's, run on both back ends;)
//   - the 2-D dispatch shape covers every sample once within the device's limits;
//   - the device's limits are read (storage buffer range, work-groups, push constants);
//   - the SPIR-V comes from the disk cache in a second sampler;
//   - errors: an unknown selector, an unknown language;
//   - negative controls: another seed fails the agreement; with
//     GGXCL_VULKAN_VALIDATION=1 (set for every suite labelled vulkan) the
//     validation layer stops a dispatch whose push constants overrun the layout.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "device_fixture.hpp"
#include "sample_agreement.hpp"
#include "scratch.hpp"
#include "vulkan_fixture.hpp"
#include "vulkan/spirv_features.hpp"  // lib/src: the capabilities a device lacks
#include "vulkan/vulkan_compute.hpp"  // lib/src: the back end's dispatch_shape

namespace {

using ggxcl::Field;
using ggxcl::ShaderLanguage;

const auto& languages = ggxvk::all_shader_languages;
const ggxcl::FieldSet every_field{Field::m, Field::o, Field::pdf_m, Field::pdf_o, Field::weight, Field::u};
constexpr std::uint64_t agreement_samples = 1 << 15;

ggxcl::VulkanSampler& vulkan(ShaderLanguage language)
{
    return ggxvk::vulkan_sampler(language);
}

ggxcl::SampleParams request(ggxcl::Method method, float ax, float ay, double theta)
{
    ggxcl::SampleParams p;
    p.method = method;
    p.alpha_x = ax;
    p.alpha_y = ggxcl::method_traits(method).isotropic_only ? ax : ay;
    p.view = ggxcl::view_from_angles(theta, 35.0);
    return p;
}

std::string label_of(ShaderLanguage language, const ggxcl::SampleParams& p, const std::string& what)
{
    return std::string(ggxcl::shader_language_name(language)) + " " + std::string(ggxcl::method_name(p.method)) +
           " " + what;
}

ggxvk::Agreement check_against_opencl(ShaderLanguage language, const ggxcl::SampleParams& p, const std::string& what,
                                      const ggxcl::PerSampleInputs& inputs = {}, std::uint64_t seed = 11)
{
    const std::uint64_t count = inputs.uniforms.empty() ? agreement_samples : inputs.uniforms.size();
    const ggxcl::SampleRange range{seed, 123456789, count};
    const ggxcl::SampleSet shader = vulkan(language).generate(p, range, every_field, inputs);
    const ggxcl::SampleSet opencl = ggxtest::sampler().generate(p, {11, range.first, range.count}, every_field, inputs);
    const ggxvk::Agreement a = ggxvk::sample_agreement(shader, opencl);
    if (seed == 11) {
        ggxvk::check_agreement_bounds(a, label_of(language, p, what));
        CHECK_MESSAGE(shader.u == opencl.u, label_of(language, p, what));
    }
    return a;
}

} // namespace

TEST_CASE("the Vulkan device and its limits")
{
    const std::vector<ggxcl::VulkanDeviceInfo> devices = ggxcl::list_vulkan_devices();
    REQUIRE(!devices.empty());
    const ggxcl::VulkanDeviceInfo& d = vulkan(ShaderLanguage::glsl).device();
    MESSAGE("Vulkan samples on " << d.label() << " (" << d.type << ", Vulkan " << d.api_version << "), against OpenCL's "
                                 << ggxtest::sampler().device_name());
    CHECK(d.int64);
    CHECK(d.max_storage_buffer_range >= (1u << 27));  // Vulkan's minimum
    CHECK(d.max_work_groups_x >= 65535);
    CHECK(d.max_push_constants >= 128);
    CHECK(vulkan(ShaderLanguage::glsl).device_name() == "vulkan:" + d.name);
}

TEST_CASE("every method's samples on Vulkan agree with OpenCL's for the same request (conductor)")
{
    ggxvk::Agreement worst;
    for (ShaderLanguage language : languages)
        for (ggxcl::Method method : ggxcl::all_methods) {
            worst = ggxvk::worst_of(worst, check_against_opencl(language, request(method, 0.3f, 0.3f, 40), "alpha 0.3, 40 degrees"));
            worst = ggxvk::worst_of(worst, check_against_opencl(language, request(method, 0.05f, 0.6f, 80), "alpha (0.05, 0.6), 80 degrees"));
            if (ggxcl::method_traits(method).views_below)
                worst = ggxvk::worst_of(worst, check_against_opencl(language, request(method, 0.4f, 0.2f, 120), "120 degrees (below)"));
        }
    MESSAGE("conductors, GLSL and HLSL, largest " << ggxvk::describe(worst));
}

TEST_CASE("every dielectric method's samples on Vulkan agree with OpenCL's")
{
    for (ShaderLanguage language : languages)
        for (ggxcl::Method method : ggxcl::all_methods) {
            if (!ggxcl::method_traits(method).dielectric)
                continue;
            ggxcl::SampleParams p = request(method, 0.25f, 0.45f, 45);
            p.eta = 1.5f;
            check_against_opencl(language, p, "eta 1.5, radiance");
            p.transport = ggxcl::Transport::importance;
            p.eta = 1.0f / 1.33f;
            check_against_opencl(language, p, "eta 1/1.33, importance");
        }
}

TEST_CASE("world space, Sobol and per-sample inputs on Vulkan agree with OpenCL")
{
    ggxcl::SampleParams world = request(ggxcl::Method::bounded, 0.35f, 0.35f, 50);
    world.world_space = true;
    world.normal = {0.3f, -0.2f, 0.9f};
    ggxcl::SampleParams sobol = request(ggxcl::Method::caps, 0.2f, 0.5f, 60);
    sobol.sequence = ggxcl::Sequence::sobol;
    ggxcl::PerSampleInputs inputs;
    for (int j = 0; j < 5000; ++j) {
        const float t = float(j) / 5000.0f;
        inputs.views.push_back(ggxcl::view_from_angles(85.0 * t, 360.0 * t));
        inputs.alphas.push_back({0.02f + t, 0.6f - 0.5f * t});
        inputs.uniforms.push_back({float(j % 97) / 97.0f, float(j % 89) / 89.0f});
    }
    for (ShaderLanguage language : languages) {
        check_against_opencl(language, world, "world space, normal (0.3, -0.2, 0.9)");
        check_against_opencl(language, sobol, "Sobol");
        check_against_opencl(language, request(ggxcl::Method::heitz, 0.3f, 0.3f, 30), "per-sample views, alphas, uniforms",
                             inputs);
    }
}

TEST_CASE("the 2-D dispatch covers every sample once within the device's limits")
{
    using ggxcl::detail::dispatch_shape;
    const auto s = dispatch_shape(1000000, 64, 65535, 65535);
    CHECK(s.groups_x == 15625);
    CHECK(s.groups_y == 1);
    const auto wide = dispatch_shape(100000, 64, 100, 65535);  // 1563 groups, 100 per row
    CHECK(wide.groups_x == 100);
    CHECK(wide.groups_y == 16);
    CHECK(wide.row_width == 6400);
    CHECK(std::uint64_t(wide.groups_x) * wide.groups_y * 64 >= 100000);
    CHECK_THROWS_AS(dispatch_shape(1ull << 40, 64, 65535, 65535), ggxcl::InvalidArgument);
}

TEST_CASE("a second Vulkan sampler reads its SPIR-V from the disk cache")
{
    const ggxtest::ScratchFolder scratch("spirv-cache");
    ::setenv("GGXCL_PROGRAM_CACHE", (scratch / "cache").c_str(), 1);
    const ggxcl::SampleParams p = request(ggxcl::Method::ndf, 0.45f, 0.45f, 20);
    ggxcl::VulkanSampler first("", ShaderLanguage::hlsl), second("", ShaderLanguage::hlsl);
    const ggxcl::SampleSet a = first.generate(p, {1, 0, 1000}, {Field::o});
    const ggxcl::SampleSet b = second.generate(p, {1, 0, 1000}, {Field::o});
    ::unsetenv("GGXCL_PROGRAM_CACHE");
    CHECK(first.shaders_built() == 1);
    CHECK(first.shaders_from_disk() == 0);
    CHECK(second.shaders_from_disk() == 1);
    CHECK(a.o == b.o);
}

TEST_CASE("bad requests on Vulkan are refused with the value and what is allowed")
{
    CHECK_THROWS_WITH_AS(ggxcl::parse_shader_language("wgsl"), doctest::Contains("glsl or hlsl"), ggxcl::InvalidArgument);
    CHECK_THROWS_WITH_AS(ggxcl::VulkanSampler("no such device"), doctest::Contains("llvmpipe"), ggxcl::NoMatchingDevice);
}

TEST_CASE("negative control: another seed fails the agreement")
{
    const ggxvk::Agreement a =
        check_against_opencl(ShaderLanguage::glsl, request(ggxcl::Method::caps, 0.3f, 0.3f, 40), "seed 12", {}, 12);
    CHECK(a.angle_99 > 1e-2);
}

TEST_CASE("negative control: the validation layer stops a dispatch that overruns its push constants")
{
    const ggxtest::ScratchFolder scratch("validation");
    const std::string command = std::string("GGXCL_VULKAN_VALIDATION=1 ") + GGX_VALIDATION_PROBE + " >" +
                                (scratch / "out.txt").string() + " 2>&1";
    const int status = std::system(command.c_str());
    const std::string out = ggxtest::read_all(scratch / "out.txt");
    CAPTURE(out);
    CHECK(status != 0);
    CHECK(out.find("ggxcl: Vulkan validation error") != std::string::npos);
    CHECK(out.find("unreported") == std::string::npos);
}

TEST_CASE("a shader's 16- and 8-bit capabilities against the device's features: the one it lacks is named")
{
    using ggxcl::detail::missing_device_feature;
    // A SPIR-V header, OpCapability Shader (1), then OpCapability Float16 (9).
    const std::vector<std::uint32_t> fp16 = {0x07230203u, 0x00010300u, 0u, 10u, 0u, (2u << 16) | 17u, 1u,
                                             (2u << 16) | 17u, 9u};
    ggxcl::VulkanDeviceInfo device;
    device.name = "test device";
    const std::string missing = missing_device_feature(fp16, device);
    CHECK(missing.find("Float16") != std::string::npos);
    CHECK(missing.find("shaderFloat16") != std::string::npos);
    CHECK(missing.find("test device") != std::string::npos);
    device.float16 = true;
    CHECK(missing_device_feature(fp16, device).empty());
    // The devices the suites run on: lavapipe offers every small type a user's shader may use.
    const ggxcl::VulkanDeviceInfo here = ggxcl::select_vulkan_device();
    CHECK(here.float16);
    CHECK(here.int16);
    CHECK(here.storage16);
}
