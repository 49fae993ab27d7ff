// test_vulkan_stress.cpp - the stability map on a Vulkan device
// (VulkanSampler::stress, kernels/ggx_stress.comp and .hlsl, through the
// maps of `ggx stress` on a Backend; lavapipe in CI), in GLSL and HLSL:
//   - every method's conductor map has no NaN or Inf and the fallback in
//     exactly the cells and cases where OpenCL's map has it; so does every
//     dielectric method's map over indices near 1 and typical;
//   - the same without the guards: the shader is built with GGX_GUARDS=0;
//   (inputs of the wrong size are refused: test_backend_contract, both back ends;)
//   - negative control: another method's OpenCL map differs in its fallback
//     cells, which the comparison sees.
#include <doctest/doctest.h>

#include <string>

#include "device_fixture.hpp"
#include "stress_dielectric.hpp"
#include "stress_run.hpp"
#include "vulkan_fixture.hpp"

namespace {

using ggxcl::ShaderLanguage;

// The cells whose counts of `kind` differ between two maps.
template <class Map>
int cells_differing(const Map& a, const Map& b, int kind)
{
    REQUIRE(a.size() == b.size());
    int differ = 0;
    for (std::size_t c = 0; c < a.size(); ++c)
        differ += a[c].failures[kind] != b[c].failures[kind] ? 1 : 0;
    return differ;
}

template <class Map>
std::uint64_t total(const Map& map, int kind)
{
    std::uint64_t n = 0;
    for (const auto& cell : map)
        n += cell.failures[kind];
    return n;
}

} // namespace

TEST_CASE("every method's map on Vulkan: no NaN or Inf, OpenCL's fallback cases, guarded or not")
{
    const ggxapp::StressAxes axes = ggxapp::stress_axes();
    for (ggxcl::Method method : ggxcl::all_methods) {
        const std::vector<ggxapp::StressCase> cases = ggxapp::stress_cases(method, axes);
        const std::vector<ggxapp::StressOutcome> reference = ggxapp::host_outcomes(method, cases);  // drawn once
        // The map of `device`'s outcomes, guarded or not.
        auto map_on = [&](ggxcl::Backend& device, bool guards) {
            return ggxapp::map_against(
                ggxapp::device_outcomes(device, method, ggxcl::Precision::precise, cases, guards), reference, cases,
                axes);
        };
        for (bool guards : {true, false}) {
            const ggxapp::StressMap cl = map_on(ggxtest::sampler(), guards);
            for (ShaderLanguage language : ggxvk::all_shader_languages) {
                CAPTURE(std::string(ggxcl::shader_language_name(language)));
                CAPTURE(ggxcl::method_name(method));
                CAPTURE(guards);
                const ggxapp::StressMap vk = map_on(ggxvk::vulkan_sampler(language), guards);
                if (guards)
                    CHECK(total(vk, ggxapp::nan_inf) == 0);
                CHECK(total(vk, ggxapp::nan_inf) == total(cl, ggxapp::nan_inf));
                CHECK(cells_differing(vk, cl, ggxapp::fallback) == 0);
                CHECK(total(vk, ggxapp::fallback) == total(cl, ggxapp::fallback));
            }
        }
    }
}

TEST_CASE("every dielectric method's map on Vulkan: no NaN or Inf, OpenCL's fallback cases")
{
    const ggxapp::StressAxes axes = ggxapp::dielectric_axes({0.9999f, 1.0001f, 1.5f, 0.5f});
    namespace dl = ggxapp::dielectric;
    for (ggxcl::Method method : ggxcl::all_methods) {
        if (!ggxcl::method_traits(method).dielectric)
            continue;
        const std::vector<ggxapp::StressCase> cases = ggxapp::dielectric_cases(method, axes);
        const dl::Map cl = dl::device_map(ggxtest::sampler(), method, ggxcl::Precision::precise, cases, axes);
        for (ShaderLanguage language : ggxvk::all_shader_languages) {
            CAPTURE(std::string(ggxcl::shader_language_name(language)));
            CAPTURE(ggxcl::method_name(method));
            const dl::Map vk = dl::device_map(ggxvk::vulkan_sampler(language), method, ggxcl::Precision::precise,
                                              cases, axes);
            CHECK(total(vk, dl::nan_inf) == 0);
            CHECK(cells_differing(vk, cl, dl::fallback) == 0);
            CHECK(total(vk, dl::fallback) > 0);
        }
    }
}

TEST_CASE("negative control: another method's map differs in its fallback cells")
{
    const ggxapp::StressAxes axes = ggxapp::stress_axes();
    const std::vector<ggxapp::StressCase> cases = ggxapp::stress_cases(ggxcl::Method::caps, axes);
    const ggxapp::StressMap vk = ggxapp::device_stress_map(ggxvk::vulkan_sampler(ShaderLanguage::glsl),
                                                           ggxcl::Method::caps, ggxcl::Precision::precise, cases, axes);
    const ggxapp::StressMap other = ggxapp::device_stress_map(ggxtest::sampler(), ggxcl::Method::caps_iso,
                                                              ggxcl::Precision::precise, cases, axes);
    CHECK(cells_differing(vk, other, ggxapp::fallback) > 0);
}
