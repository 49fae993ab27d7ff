// test_shaders.cpp - the device headers as GLSL 4.50 and as HLSL (glslang's
// front ends through shaderc), run in compute shaders on a Vulkan device
// (Mesa's lavapipe in CI) and checked against the OpenCL device (PoCL):
//   - the uniforms of ggx_philox.h and ggx_sobol.h (64-bit integers) equal
//     the C++ build of the same headers bit for bit;
//   - every method's samples from the caller's uniforms agree with OpenCL's
//     from the same uniforms, conductor and dielectric: the angle of m and
//     of o 99% <= 1e-5 rad and max <= 2e-3, pdf_o relative 99% <= 1e-4, and
//     the pdf function's of the shader's o against OpenCL's of the same o;
//     no NaN or Inf;
//   - a chi-square of the shader's o against the reference pdf passes for
//     every method (conductor, 1e6 samples) and dielectric method (4e5),
//     Sidak-corrected over the tests;
//   - negative controls: ndf's samples fail caps' pdf, uniforms shifted by
//     one sample fail the agreement, and a shader with a syntax error fails
//     to build naming its file and line.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "device_fixture.hpp"
#include "distribution_check.hpp"
#include "error_bounds.hpp"
#include "ggx_sobol.h"
#include "sample_agreement.hpp"
#include "shader_samples.hpp"
#include "test_paths.hpp"

namespace {

using ggxvk::ShaderLanguage;

constexpr std::uint64_t agreement_samples = 1 << 16;

using ggxvk::Agreement;

Agreement agreement(const ggxcl::SampleParams& params, const std::vector<float>& shader_uniforms,
                    const std::vector<float>& opencl_uniforms, ShaderLanguage language)
{
    const ggxvk::ShaderSamples shader = ggxvk::shader_samples(language, params, shader_uniforms);
    std::vector<ggxcl::Vec3> directions;
    for (std::size_t j = 0; j < shader.set.count; ++j)
        directions.push_back(shader.set.o_at(j));
    return ggxvk::sample_agreement(shader.set, ggxvk::opencl_samples(params, opencl_uniforms), shader.pdf,
                                   ggxtest::sampler().pdf(params, directions));
}

// The largest of each measure over the requests checked so far, for the report.
Agreement worst;

void report_worst(const char* what)
{
    MESSAGE(std::string(what) << ": largest " << ggxvk::describe(worst));
    worst = {};
}

void check_agreement(ShaderLanguage language, const ggxcl::SampleParams& params, const std::string& label)
{
    const std::vector<float> u = ggxvk::random_uniforms(7, agreement_samples);
    const Agreement a = agreement(params, u, u, language);
    ggxvk::check_agreement_bounds(a, std::string(ggxvk::language_name(language)) + " " +
                                         std::string(ggxcl::method_name(params.method)) + " " + label);
    worst = ggxvk::worst_of(worst, a);
}

struct Request {
    float ax, ay, theta;
    const char* label;
};

ggxcl::SampleParams params_of(ggxcl::Method method, const Request& r)
{
    ggxcl::SampleParams p;
    p.method = method;
    p.alpha_x = r.ax;
    p.alpha_y = ggxcl::method_traits(method).isotropic_only ? r.ax : r.ay;
    p.view = ggxcl::view_from_angles(r.theta, 35.0);
    return p;
}

// Views above and below the horizon (below only where the method's traits allow), rough and smooth.
std::vector<Request> conductor_requests(ggxcl::Method method)
{
    std::vector<Request> requests{{0.3f, 0.3f, 40.0f, "alpha 0.3, 40 degrees"},
                                  {0.05f, 0.6f, 80.0f, "alpha (0.05, 0.6), 80 degrees"},
                                  {1.5f, 1.2f, 10.0f, "alpha (1.5, 1.2), 10 degrees"}};
    if (ggxcl::method_traits(method).views_below) {
        requests.push_back({0.4f, 0.2f, 120.0f, "alpha (0.4, 0.2), 120 degrees (below)"});
        // Near -n, where the cancelling forms and the exact ones differ by 3.5e-2 rad (test_below_horizon's control).
        requests.push_back({0.05f, 0.05f, 179.0f, "alpha 0.05, 179 degrees (near -n)"});
    }
    return requests;
}

std::vector<ggxcl::Method> dielectric_methods()
{
    std::vector<ggxcl::Method> methods;
    for (ggxcl::Method method : ggxcl::all_methods)
        if (ggxcl::method_traits(method).dielectric)
            methods.push_back(method);
    return methods;
}

ggxcl::SampleParams dielectric_params(ggxcl::Method method, float eta, ggxcl::Transport transport, float theta)
{
    ggxcl::SampleParams p = params_of(method, {0.25f, 0.45f, theta, ""});
    p.eta = eta;
    p.transport = transport;
    return p;
}

} // namespace

TEST_CASE("Vulkan device")
{
    MESSAGE("shaders run on " << ggxvk::vulkan().name() << ", compared with OpenCL's "
                              << ggxtest::sampler().device_name());
}

TEST_CASE("the uniforms of ggx_philox.h and ggx_sobol.h in GLSL and HLSL equal the C++ build's bit for bit")
{
    const std::uint64_t seed = (std::uint64_t(5) << 32) + 77, first = (std::uint64_t(1) << 32) - 500;
    const std::uint32_t n = 1000;  // crosses a 2^32 block: Sobol's keys change there
    const std::uint32_t request[5] = {std::uint32_t(seed), std::uint32_t(seed >> 32), std::uint32_t(first),
                                      std::uint32_t(first >> 32), n};
    std::vector<float> expected(9 * std::size_t(n));
    for (std::uint32_t j = 0; j < n; ++j) {
        const ggx_uniform_pair p = ggx_philox_pair(seed, first + j), s = ggx_sobol_pair(seed, first + j),
                               l = ggx_sobol_launch_pair(seed, first, j);
        const float values[9] = {p.u1, p.u2, ggx_lobe_uniform(seed, first + j), s.u1, s.u2,
                                 ggx_sobol_lobe_uniform(seed, first + j), l.u1, l.u2,
                                 ggx_sobol_launch_lobe_uniform(seed, first, j)};
        for (int k = 0; k < 9; ++k)
            expected[std::size_t(k) * n + j] = values[k];
    }
    for (ShaderLanguage language : ggxvk::all_shader_languages) {
        const std::string file = ggxtest::vulkan_shader_dir() + (language == ShaderLanguage::hlsl ? "/uniforms.hlsl" : "/uniforms.comp");
        const auto spirv = ggxvk::compile_compute_shader({language, file, ggxvk::read_text_file(file), {}},
                                                         {ggxtest::kernel_dir()});
        std::vector<float> values(expected.size(), -1.0f);
        ggxvk::vulkan().run(spirv, request, sizeof request, {ggxvk::host_array(values)}, (n + 63) / 64);
        CAPTURE(ggxvk::language_name(language));
        CHECK(values == expected);
    }
}

TEST_CASE("every method's shader samples agree with OpenCL's from the same uniforms (conductor)")
{
    for (ShaderLanguage language : ggxvk::all_shader_languages)
        for (ggxcl::Method method : ggxcl::all_methods)
            for (const Request& r : conductor_requests(method))
                check_agreement(language, params_of(method, r), r.label);
    report_worst("conductors, GLSL and HLSL");
}

TEST_CASE("every dielectric method's shader samples agree with OpenCL's from the same uniforms")
{
    for (ShaderLanguage language : ggxvk::all_shader_languages)
        for (ggxcl::Method method : dielectric_methods()) {
            check_agreement(language, dielectric_params(method, 1.5f, ggxcl::Transport::radiance, 45.0f),
                            "eta 1.5, radiance, 45 degrees");
            if (ggxcl::method_traits(method).views_below)
                check_agreement(language, dielectric_params(method, 1.33f, ggxcl::Transport::importance, 130.0f),
                                "eta 1.33, importance, 130 degrees (below)");
        }
    report_worst("dielectrics, GLSL and HLSL");
}

TEST_CASE("negative control: uniforms shifted by one sample fail the agreement")
{
    const ggxcl::SampleParams params = params_of(ggxcl::Method::caps, {0.3f, 0.3f, 40.0f, ""});
    std::vector<float> u = ggxvk::random_uniforms(7, agreement_samples), shifted = u;
    std::rotate(shifted.begin(), shifted.begin() + 1, shifted.end());
    const Agreement a = agreement(params, shifted, u, ShaderLanguage::glsl);
    CHECK(a.angle_99 > 1e-2);
}

TEST_CASE("negative control: a shader with a syntax error fails to build, naming its file and line")
{
    for (ShaderLanguage language : ggxvk::all_shader_languages) {
        const std::string text = language == ShaderLanguage::hlsl
                                     ? "#include \"ggx_samplers.h\"\n[numthreads(1, 1, 1)]\nvoid main() { float x = ; }\n"
                                     : "#version 450\n#extension GL_GOOGLE_include_directive : require\n#include \"ggx_samplers.h\"\nlayout(local_size_x = 1) in;\n"
                                       "void main() { float x = ; }\n";
        std::string message;
        try {
            ggxvk::compile_compute_shader({language, "broken.shader", text, {}}, {ggxtest::kernel_dir()});
        } catch (const std::runtime_error& e) {
            message = e.what();
        }
        CAPTURE(message);
        CHECK(message.find(language == ShaderLanguage::hlsl ? "broken.shader:3" : "broken.shader:5") !=
              std::string::npos);
    }
}
