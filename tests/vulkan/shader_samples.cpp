// shader_samples.cpp - the sample shaders run on Vulkan and the same
// request on OpenCL.
#include "shader_samples.hpp"

#include <map>
#include <random>
#include <string>
#include <tuple>

#include "device_fixture.hpp"
#include "test_paths.hpp"

namespace ggxvk {

namespace {

// The push constants of sample.comp / sample.hlsl.
struct Request {
    float view_x, view_y, view_z, alpha_x, alpha_y, eta;
    std::int32_t radiance;
    std::uint32_t count;
};

constexpr std::uint32_t group_size = 64;

} // namespace

ComputeDevice& vulkan()
{
    // Never destroyed: destroying the instance unloads the driver, whose own
    // allocations LeakSanitizer then reports in frames it cannot name.
    static ComputeDevice* device = new ComputeDevice;
    return *device;
}

const std::vector<std::uint32_t>& sample_shader(ShaderLanguage language, ggxcl::Method method, bool dielectric)
{
    static std::map<std::tuple<ShaderLanguage, ggxcl::Method, bool>, std::vector<std::uint32_t>> compiled;
    auto key = std::make_tuple(language, method, dielectric);
    auto found = compiled.find(key);
    if (found != compiled.end())
        return found->second;
    const std::string file = ggxtest::vulkan_shader_dir() + "/sample." +
                             (language == ShaderLanguage::hlsl ? "hlsl" : "comp");
    const std::string id = std::to_string(static_cast<int>(method));
    ShaderSource source{language, file, read_text_file(file),
                        {{"GGX_TEST_METHOD", id}, {"GGX_ONLY_METHOD", id}, {"GGX_TEST_DIELECTRIC", dielectric ? "1" : "0"}}};
    return compiled[key] = compile_compute_shader(source, {ggxtest::kernel_dir()});
}

std::vector<float> random_uniforms(std::uint64_t seed, std::uint64_t count)
{
    std::mt19937_64 generator(seed);
    std::vector<float> planes(3 * count);
    for (float& u : planes)
        u = float(generator() >> 40) * 0x1p-24f;
    return planes;
}

ShaderSamples shader_samples(ShaderLanguage language, const ggxcl::SampleParams& params,
                             const std::vector<float>& uniforms)
{
    const std::uint32_t n = std::uint32_t(uniforms.size() / 3);
    const bool dielectric = params.eta != 0.0f;
    const Request request{params.view.x, params.view.y, params.view.z, params.alpha_x, params.alpha_y, params.eta,
                          params.transport == ggxcl::Transport::radiance ? 1 : 0, n};
    std::vector<float> in = uniforms, out(std::size_t(10) * n);
    vulkan().run(sample_shader(language, params.method, dielectric), &request, sizeof request,
                 {host_array(in), host_array(out)}, (n + group_size - 1) / group_size);
    ShaderSamples s;
    s.set.count = n;
    auto plane = [&](int first, int planes) {
        return std::vector<float>(out.begin() + std::ptrdiff_t(first) * n, out.begin() + std::ptrdiff_t(first + planes) * n);
    };
    s.set.m = plane(0, 3);
    s.set.o = plane(3, 3);
    s.set.pdf_m = plane(6, 1);
    s.set.pdf_o = plane(7, 1);
    s.set.weight = plane(8, 1);
    s.pdf = plane(9, 1);
    return s;
}

ggxcl::SampleSet opencl_samples(const ggxcl::SampleParams& params, const std::vector<float>& uniforms)
{
    const std::size_t n = uniforms.size() / 3;
    ggxcl::PerSampleInputs inputs;
    for (std::size_t j = 0; j < n; ++j)
        inputs.uniforms.push_back({uniforms[j], uniforms[n + j]});
    if (params.eta != 0.0f)
        inputs.lobe_uniforms.assign(uniforms.begin() + std::ptrdiff_t(2 * n), uniforms.end());
    return ggxtest::sampler().generate(params, {0, 0, n},
                                       {ggxcl::Field::m, ggxcl::Field::o, ggxcl::Field::pdf_m, ggxcl::Field::pdf_o,
                                        ggxcl::Field::weight},
                                       inputs);
}

} // namespace ggxvk
