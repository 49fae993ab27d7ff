// test_vulkan_user_sampler.cpp - user samplers in GLSL and HLSL through the
// runtime's Vulkan back end (VulkanSampler; lavapipe in CI):
//   - a GLSL copy of caps (vec3s, a helper file of its own by relative path)
//     gives the built-in caps' bits on Vulkan: samples in both sequences,
//     pdf, furnace, histogram and stress map; so does the OpenCL C copy of
//     caps read as HLSL, whatever the sampler's own language;
//   - an HLSL sampler of m alone is completed as heitz's samples are;
//   - the language follows the extension; a shader sampler is refused by
//     Sampler (OpenCL) and an OpenCL C one by VulkanSampler, naming the file;
//   - a file without its pdf is refused before any build; one that does not
//     compile is a BuildError starting with its file and line.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "bit_compare.hpp"
#include "completed_samples.hpp"
#include "discarded_counts.hpp"
#include "device_fixture.hpp"
#include "stress_run.hpp"
#include "test_paths.hpp"
#include "vulkan_fixture.hpp"

namespace {

using ggxcl::ShaderLanguage;
using ggxtest::same_bits;

using ggxtest::user_sampler_file;

ggxcl::SampleParams user_params(std::shared_ptr<const ggxcl::UserSampler> sampler)
{
    ggxcl::SampleParams p;
    p.method = ggxcl::Method::user;
    p.user_sampler = std::move(sampler);
    p.alpha_x = 0.2f;
    p.alpha_y = 0.5f;
    p.view = ggxcl::view_from_angles(70.0, 20.0);
    return p;
}

ggxcl::SampleParams as_method(ggxcl::SampleParams p, ggxcl::Method method)
{
    p.method = method;
    p.user_sampler = nullptr;
    return p;
}

std::vector<ggxcl::Vec3> directions_of(const ggxcl::SampleSet& s)
{
    std::vector<ggxcl::Vec3> directions;
    for (std::size_t j = 0; j < s.count; ++j)
        directions.push_back(s.o_at(j));
    return directions;
}

// `user` against the built-in caps on `vk`, in `caps_language`: every job's bits.
void check_caps_bits(const ggxcl::SampleParams& user, ShaderLanguage caps_language, ggxcl::VulkanSampler& vk)
{
    const ggxcl::SampleParams caps = as_method(user, ggxcl::Method::caps);
    ggxcl::VulkanSampler& reference = ggxvk::vulkan_sampler(caps_language);
    const ggxcl::SampleRange range{7, 1000, 4099};
    for (ggxcl::Sequence sequence : ggxcl::all_sequences) {
        CAPTURE(ggxcl::sequence_name(sequence));
        ggxcl::SampleParams u = user, c = caps;
        u.sequence = c.sequence = sequence;
        CHECK(same_bits(vk.generate(u, range, ggxcl::FieldSet::all()),
                        reference.generate(c, range, ggxcl::FieldSet::all())));
    }
    const std::vector<ggxcl::Vec3> directions = directions_of(reference.generate(caps, range, {ggxcl::Field::o}));
    CHECK(same_bits(vk.pdf(user, directions), reference.pdf(caps, directions)));
    const ggxcl::FurnaceSums a = vk.furnace(user, range), b = reference.furnace(caps, range);
    CHECK(a.sum == b.sum);
    CHECK(a.sum_of_squares == b.sum_of_squares);
    ggxtest::check_counts_with_discards(vk.histogram(user, range, 16, 32), reference.histogram(caps, range, 16, 32));
}

} // namespace

TEST_CASE("a GLSL copy of caps, and the OpenCL C copy read as HLSL, give caps' bits on Vulkan")
{
    const auto glsl = ggxcl::UserSampler::load(user_sampler_file("shaders/caps_copy.glsl"));
    CHECK(glsl->shader_language() == ShaderLanguage::glsl);
    CHECK(glsl->language_name() == "GLSL");
    CHECK(glsl->name() == "caps_copy");
    CHECK(glsl->distribution() == ggxcl::Distribution::vndf);
    CHECK(glsl->source().find("#version") == std::string::npos);
    check_caps_bits(user_params(glsl), ShaderLanguage::glsl, ggxvk::vulkan_sampler(ShaderLanguage::glsl));

    // The OpenCL C file in HLSL: compiled as HLSL though the sampler's own shaders are GLSL.
    const auto hlsl = ggxcl::UserSampler::load(user_sampler_file("caps_copy.h"), "", ShaderLanguage::hlsl);
    CHECK(hlsl->shader_language() == ShaderLanguage::hlsl);
    CHECK(hlsl->key() != ggxcl::UserSampler::load(user_sampler_file("caps_copy.h"))->key());
    check_caps_bits(user_params(hlsl), ShaderLanguage::hlsl, ggxvk::vulkan_sampler(ShaderLanguage::glsl));
}

TEST_CASE("a user sampler's stress map on Vulkan is the built-in caps' map")
{
    const auto glsl = ggxcl::UserSampler::load(user_sampler_file("shaders/caps_copy.glsl"));
    const ggxapp::StressAxes axes = ggxapp::stress_axes();
    const std::vector<ggxapp::StressCase> cases = ggxapp::stress_cases(ggxcl::Method::user, axes);
    ggxcl::VulkanSampler& vk = ggxvk::vulkan_sampler(ShaderLanguage::glsl);
    const ggxapp::StressMap mine =
        ggxapp::device_stress_map(vk, ggxcl::Method::user, ggxcl::Precision::precise, cases, axes, true, glsl.get());
    const ggxapp::StressMap caps =
        ggxapp::device_stress_map(vk, ggxcl::Method::caps, ggxcl::Precision::precise, cases, axes, true);
    REQUIRE(mine.size() == caps.size());
    for (std::size_t c = 0; c < mine.size(); ++c) {  // the accuracy kinds apart: a user sampler has no reference
        CHECK(mine[c].cases == caps[c].cases);
        CHECK(std::equal(mine[c].failures.begin(), mine[c].failures.begin() + ggxapp::inaccurate,
                         caps[c].failures.begin()));
    }
    const std::vector<float> in(10 * 4, 0.5f);
    CHECK_THROWS_AS(vk.stress({ggxcl::Method::user}, in, 4), ggxcl::InvalidArgument);
    CHECK_THROWS_AS(vk.stress({ggxcl::Method::caps, ggxcl::Precision::precise, true, false, glsl.get()}, in, 4), ggxcl::InvalidArgument);
}

TEST_CASE("an HLSL sampler of m alone is completed: heitz's m, o and weight, its own pdf")
{
    const auto mine_sampler = ggxcl::UserSampler::load(user_sampler_file("shaders/heitz_normal_only.hlsl"));
    CHECK(mine_sampler->samples_m());
    const ggxcl::SampleParams user = user_params(mine_sampler);
    ggxcl::VulkanSampler& vk = ggxvk::vulkan_sampler(ShaderLanguage::hlsl);
    const ggxcl::SampleRange range{3, 0, 5000};
    const ggxcl::SampleSet mine = vk.generate(user, range, ggxcl::FieldSet::all());
    const ggxcl::SampleSet heitz = vk.generate(as_method(user, ggxcl::Method::heitz), range, ggxcl::FieldSet::all());
    ggxtest::check_completed_like_heitz(mine, heitz);
}

TEST_CASE("each API refuses the other's user samplers, naming the file; Vulkan refuses a user sampler on glass")
{
    const std::string glsl_file = user_sampler_file("shaders/caps_copy.glsl");
    const std::string cl_file = user_sampler_file("caps_copy.h");
    const std::string on_opencl = ggxtest::message_of<ggxcl::InvalidArgument>([&] {
        ggxtest::sampler().generate(user_params(ggxcl::UserSampler::load(glsl_file)), {0, 0, 10}, {ggxcl::Field::o});
    });
    CHECK(on_opencl.find(glsl_file) != std::string::npos);
    CHECK(on_opencl.find("GLSL") != std::string::npos);
    const std::string on_vulkan = ggxtest::message_of<ggxcl::InvalidArgument>([&] {
        ggxvk::vulkan_sampler(ShaderLanguage::glsl)
            .generate(user_params(ggxcl::UserSampler::load(cl_file)), {0, 0, 10}, {ggxcl::Field::o});
    });
    CHECK(on_vulkan.find(cl_file) != std::string::npos);
    CHECK(on_vulkan.find("OpenCL C") != std::string::npos);
    ggxcl::SampleParams glass = user_params(ggxcl::UserSampler::load(glsl_file)), world = glass;
    glass.eta = 1.5f;
    world.world_space = true;
    for (const ggxcl::SampleParams& p : {glass, world})  // a user sampler is a tangent-space conductor's
        CHECK_THROWS_AS(ggxvk::vulkan_sampler(ShaderLanguage::glsl).generate(p, {0, 0, 10}, {ggxcl::Field::o}),
                        ggxcl::InvalidArgument);
    CHECK_FALSE(ggxcl::shader_language_of_file("x.h").has_value());
    CHECK(ggxcl::shader_language_of_file("dir.v2/x.hlsl") == ShaderLanguage::hlsl);
}

TEST_CASE("a shader sampler without its pdf is refused before a build; one that does not compile names its line")
{
    const std::string missing = ggxtest::message_of<ggxcl::InvalidArgument>(
        [&] { ggxcl::UserSampler::load(user_sampler_file("shaders/no_pdf.glsl")); });
    CHECK(missing.find("no_pdf.glsl") != std::string::npos);
    CHECK(missing.find("ggx_user_pdf") != std::string::npos);
    const std::string file = user_sampler_file("shaders/undeclared_name.hlsl");
    for (ShaderLanguage language : ggxvk::all_shader_languages) {
        const std::string what = ggxtest::message_of<ggxcl::BuildError>([&] {
            ggxvk::vulkan_sampler(language).generate(user_params(ggxcl::UserSampler::load(file)), {0, 0, 10},
                                                     {ggxcl::Field::o});
        });
        CAPTURE(what);
        CHECK(what.rfind("the user sampler does not compile: " + file + ":9:", 0) == 0);
    }
}

TEST_CASE("a GLSL sampler computing in float16_t inside runs clean under the validation layer: the device has "
          "shaderFloat16 enabled")
{
    // This suite runs with GGXCL_VULKAN_VALIDATION=1: a shader declaring the Float16 capability on a
    // device created without shaderFloat16 is a validation error that stops the process.
    ggxcl::VulkanSampler& vk = ggxvk::vulkan_sampler(ShaderLanguage::glsl);
    REQUIRE(ggxcl::select_vulkan_device().float16);
    const auto half = ggxcl::UserSampler::load(user_sampler_file("shaders/fp16_inside.glsl"));
    const ggxcl::SampleParams user = user_params(half);
    const ggxcl::SampleRange range{5, 0, 4096};
    const ggxcl::SampleSet mine = vk.generate(user, range, ggxcl::FieldSet::all());
    // Unit normals above the surface within half precision's rounding, each with a density.
    std::size_t bad = 0;
    for (std::size_t j = 0; j < mine.count; ++j) {
        const ggxcl::Vec3 m = mine.m_at(j);
        const double length = std::sqrt(double(m.x) * m.x + double(m.y) * m.y + double(m.z) * m.z);
        bad += !(std::fabs(length - 1.0) < 2e-3 && m.z >= 0.0f && std::isfinite(mine.pdf_m[j]));
    }
    CHECK(bad == 0);
}
