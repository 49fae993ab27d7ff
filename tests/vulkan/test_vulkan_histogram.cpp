// test_vulkan_histogram.cpp - histograms binned on a Vulkan device
// (VulkanSampler::histogram, kernels/ggx_histogram.comp and .hlsl; lavapipe
// in CI), in GLSL and HLSL:
//   - every method's conductor histogram of o (1e6 samples, 24 x 48 bins of
//     equal solid angle) fits the reference's bin probabilities, and every
//     dielectric method's over the sphere with its invalid samples counted
//     apart, Sidak-corrected to a family level of 0.01 over all;
//   - the counts equal OpenCL's histogram of the same request but for
//     samples within float rounding of a bin edge (o and m);
//   - more bins than shared memory holds are refused, naming the limit;
//   - negative controls: ndf's histogram fails caps' pdf, a dielectric's
//     fails another eta.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "device_fixture.hpp"
#include "distribution_check.hpp"
#include "vulkan_fixture.hpp"

namespace {

using ggxcl::ShaderLanguage;

const auto& languages = ggxvk::all_shader_languages;
constexpr std::uint64_t dielectric_samples = 400000;

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

int tests_in_family()
{
    int dielectrics = 0;
    for (ggxcl::Method method : ggxcl::all_methods)
        dielectrics += ggxcl::method_traits(method).dielectric ? 1 : 0;
    return int(std::size(languages)) * (int(ggxcl::all_methods.size()) + dielectrics);
}

// The p-value of the Vulkan histogram of `sampled` against the bin probabilities of `tested`.
double p_value(ShaderLanguage language, const ggxcl::SampleParams& sampled, const ggxcl::SampleParams& tested,
               std::uint64_t seed, std::uint64_t count)
{
    const ggxcl::Histogram h =
        vulkan(language).histogram(sampled, {seed, 0, count}, ggxtest::bins_z, ggxtest::bins_phi);
    CHECK(h.total() == count);
    CHECK(h.non_finite == 0);
    const auto expected =
        ggxbridge::bin_probabilities(tested.method, tested, ggxtest::bins_z, ggxtest::bins_phi, ggxcl::Field::o);
    return ggxbridge::histogram_fit(h, expected, tested.eta != 0.0f).p_value;
}

} // namespace

TEST_CASE("every method's histogram on Vulkan fits its pdf, conductor and dielectric")
{
    const double level = ggxref::sidak_level(ggxtest::family_level, tests_in_family());
    std::uint64_t seed = 500;
    for (ShaderLanguage language : languages)
        for (ggxcl::Method method : ggxcl::all_methods) {
            const std::string label = std::string(ggxcl::shader_language_name(language)) + " " +
                                      std::string(ggxcl::method_name(method));
            const ggxcl::SampleParams c = conductor(method);
            const double p = p_value(language, c, c, ++seed, ggxtest::chi_square_samples);
            INFO(label, " conductor: p = ", p, ", level ", level);
            CHECK(p > level);
            if (!ggxcl::method_traits(method).dielectric)
                continue;
            const ggxcl::SampleParams d = dielectric(method, 1.5f);
            const double q = p_value(language, d, d, ++seed, dielectric_samples);
            INFO(label, " dielectric: p = ", q, ", level ", level);
            CHECK(q > level);
        }
}

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

TEST_CASE("negative controls: a Vulkan histogram fails a wrong distribution")
{
    for (ShaderLanguage language : languages) {
        CAPTURE(std::string(ggxcl::shader_language_name(language)));
        CHECK(p_value(language, conductor(ggxcl::Method::ndf), conductor(ggxcl::Method::caps), 600,
                      ggxtest::chi_square_samples) < 1e-6);
        CHECK(p_value(language, dielectric(ggxcl::Method::caps, 1.5f), dielectric(ggxcl::Method::caps, 1.3f), 601,
                      dielectric_samples) < 1e-6);
    }
}
