// test_shader_chi_square.cpp - goodness of fit of the directions that the
// GLSL and HLSL builds of the device headers sample on a Vulkan device
// (lavapipe in CI): every method as a conductor (1e6 samples of o in the
// hemisphere bins of test_chi_square) and every dielectric method (4e5
// samples over the sphere, the samples without density in a bin of their
// own, as test_dielectric_chi_square), against the reference's bin
// probabilities, Sidak-corrected to a family level of 0.01 over all.
// Negative controls: ndf's samples against caps' pdf, and caps' dielectric
// samples against a different eta, are rejected.
#include <doctest/doctest.h>

#include <string>

#include "distribution_check.hpp"
#include "shader_samples.hpp"
#include "vulkan_fixture.hpp"

namespace {

using ggxvk::ShaderLanguage;

constexpr std::uint64_t dielectric_samples = 400000;
constexpr int dielectric_nz = 24, dielectric_nphi = 48;

ggxcl::SampleParams conductor(ggxcl::Method method)
{
    return ggxvk::chi_square_conductor(method);
}

ggxcl::SampleParams dielectric(ggxcl::Method method, float eta)
{
    return ggxvk::chi_square_dielectric(method, eta);
}

// The p-value of the shader's conductor samples of `sampled` against `tested`'s pdf.
double conductor_p_value(ShaderLanguage language, const ggxcl::SampleParams& sampled, ggxcl::Method tested,
                         std::uint64_t seed)
{
    ggxcl::SampleParams tested_params = sampled;
    tested_params.method = tested;
    const ggxvk::ShaderSamples s =
        ggxvk::shader_samples(language, sampled, ggxvk::random_uniforms(seed, ggxtest::chi_square_samples));
    const auto histogram = ggxtest::histogram_of(s.set.o, s.set.count, ggxtest::bins_z, ggxtest::bins_phi);
    return ggxref::chi_square_gof_float(histogram, ggxbridge::bin_probabilities(tested, tested_params, ggxtest::bins_z,
                                                                                ggxtest::bins_phi, ggxcl::Field::o))
        .p_value;
}

// The p-value of the shader's dielectric samples of `sampled` against the pdf of `tested`'s eta.
double dielectric_p_value(ShaderLanguage language, const ggxcl::SampleParams& sampled, float tested_eta,
                          std::uint64_t seed)
{
    const ggxvk::ShaderSamples s =
        ggxvk::shader_samples(language, sampled, ggxvk::random_uniforms(seed, dielectric_samples));
    ggxcl::Histogram h;
    h.bins_z = dielectric_nz;
    h.bins_phi = dielectric_nphi;
    std::vector<float> valid;  // planar o of the samples with a density
    std::vector<std::size_t> kept;
    for (std::size_t j = 0; j < s.set.count; ++j)
        s.set.pdf_o[j] > 0.0f ? kept.push_back(j) : void(++h.invalid);
    for (int c = 0; c < 3; ++c)
        for (std::size_t j : kept)
            valid.push_back(s.set.o[std::size_t(c) * s.set.count + j]);
    h.counts = ggxtest::histogram_of(valid, kept.size(), dielectric_nz, dielectric_nphi);
    ggxcl::SampleParams tested = sampled;
    tested.eta = tested_eta;
    const auto expected =
        ggxbridge::bin_probabilities(sampled.method, tested, dielectric_nz, dielectric_nphi, ggxcl::Field::o);
    return ggxbridge::histogram_fit(h, expected, true).p_value;
}

int dielectric_count()
{
    int count = 0;
    for (ggxcl::Method method : ggxcl::all_methods)
        count += ggxcl::method_traits(method).dielectric ? 1 : 0;
    return count;
}

double level()
{
    const int tests = int(std::size(ggxvk::all_shader_languages)) * (int(ggxcl::all_methods.size()) + dielectric_count());
    return ggxref::sidak_level(ggxtest::family_level, tests);
}

} // namespace

TEST_CASE("the shaders' conductor samples follow each method's pdf")
{
    std::uint64_t seed = 100;
    for (ShaderLanguage language : ggxvk::all_shader_languages)
        for (ggxcl::Method method : ggxcl::all_methods) {
            const double p = conductor_p_value(language, conductor(method), method, ++seed);
            INFO(std::string(ggxvk::language_name(language)), " ", ggxcl::method_name(method), ": p = ", p, ", level ", level());
            CHECK(p > level());
        }
}

TEST_CASE("the shaders' dielectric samples follow each dielectric method's pdf")
{
    std::uint64_t seed = 200;
    for (ShaderLanguage language : ggxvk::all_shader_languages)
        for (ggxcl::Method method : ggxcl::all_methods) {
            if (!ggxcl::method_traits(method).dielectric)
                continue;
            const double p = dielectric_p_value(language, dielectric(method, 1.5f), 1.5f, ++seed);
            INFO(std::string(ggxvk::language_name(language)), " ", ggxcl::method_name(method), ": p = ", p, ", level ", level());
            CHECK(p > level());
        }
}

TEST_CASE("negative controls: the shaders' samples fail a wrong distribution")
{
    for (ShaderLanguage language : ggxvk::all_shader_languages) {
        const std::string language_label = ggxvk::language_name(language);
        CAPTURE(language_label);
        CHECK(conductor_p_value(language, conductor(ggxcl::Method::ndf), ggxcl::Method::caps, 300) < 1e-6);
        CHECK(dielectric_p_value(language, dielectric(ggxcl::Method::caps, 1.5f), 1.3f, 301) < 1e-6);
    }
}
