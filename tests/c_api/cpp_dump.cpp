// cpp_dump.cpp - what the C++ API's enqueue gives for the requests of
// c_api_cases.h: each case's six fields, then enqueue_pdf and enqueue_eval
// of the sampled o, written as raw floats (CASE_FLOATS per case, in order)
// to the file argv[1] for c_consumer.c; argv[2] holds tests/user_samplers.
// With argv[3] "vulkan", what a VulkanSampler's generate, pdf and eval give
// (the user sampler: CASE_USER_SHADER), in the same layout.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "ggxcl/ggxcl.hpp"

#include "c_api_cases.h"

namespace {

std::vector<float> read(cl::CommandQueue& queue, const cl::Buffer& buffer, std::size_t floats)
{
    std::vector<float> host(floats);
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, floats * sizeof(float), host.data());
    return host;
}

ggxcl::SampleParams case_params(const api_case& c, const std::string& user_dir, bool vulkan)
{
    ggxcl::SampleParams params;
    params.method = static_cast<ggxcl::Method>(c.method);
    params.alpha_x = case_alpha_x(&c);
    params.alpha_y = case_alpha_y(&c);
    params.view = {case_view[0], case_view[1], case_view[2]};
    params.eta = c.eta;
    params.transport = c.importance ? ggxcl::Transport::importance : ggxcl::Transport::radiance;
    if (c.method == GGX_METHOD_USER)
        params.user_sampler = ggxcl::UserSampler::load(user_dir + "/" + (vulkan ? CASE_USER_SHADER : CASE_USER_FILE));
    return params;
}

// One case's floats: each field's planes packed CASE_COUNT apart (u padded to 3 planes).
std::vector<float> dump_case(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params)
{
    cl::CommandQueue& queue = sampler.queue();
    ggxcl::DeviceOutputs out;
    for (ggxcl::Field field : ggxcl::all_fields)
        out.of(field) = cl::Buffer(sampler.context(), CL_MEM_READ_WRITE, sizeof(float) * 3 * CASE_STRIDE);
    sampler.enqueue(queue, params, {CASE_SEED, CASE_FIRST, CASE_COUNT}, out, CASE_STRIDE);
    cl::Buffer pdf(sampler.context(), CL_MEM_READ_WRITE, sizeof(float) * CASE_STRIDE);
    cl::Buffer value(sampler.context(), CL_MEM_READ_WRITE, sizeof(float) * CASE_STRIDE);
    sampler.enqueue_pdf(queue, params, CASE_COUNT, out.o, pdf, CASE_STRIDE);
    sampler.enqueue_eval(queue, params, CASE_COUNT, out.o, value, CASE_STRIDE);
    std::vector<float> floats;
    auto add = [&](const cl::Buffer& buffer, int planes, int padded) {
        const std::vector<float> host = read(queue, buffer, static_cast<std::size_t>(planes) * CASE_STRIDE);
        for (int c = 0; c < planes; ++c)
            floats.insert(floats.end(), host.begin() + c * CASE_STRIDE, host.begin() + c * CASE_STRIDE + CASE_COUNT);
        floats.resize(floats.size() + static_cast<std::size_t>(padded - planes) * CASE_COUNT, 0.0f);
    };
    for (ggxcl::Field field : ggxcl::all_fields) {
        const int planes = ggxcl::field_columns(field, params.eta != 0.0f);
        add(out.of(field), planes, field == ggxcl::Field::u ? 3 : planes);
    }
    add(pdf, 1, 1);
    add(value, 1, 1);
    return floats;
}

// The same floats from a back end's host calls: generate, then pdf and eval of the sampled o.
std::vector<float> dump_host_case(ggxcl::Backend& backend, const ggxcl::SampleParams& params)
{
    const ggxcl::SampleSet s = backend.generate(params, {CASE_SEED, CASE_FIRST, CASE_COUNT}, ggxcl::FieldSet::all());
    std::vector<ggxcl::Vec3> o(CASE_COUNT);
    for (std::size_t j = 0; j < CASE_COUNT; ++j)
        o[j] = s.o_at(j);
    std::vector<float> floats;
    for (ggxcl::Field field : ggxcl::all_fields) {
        const std::vector<float>& planes = s.column_source(field);
        floats.insert(floats.end(), planes.begin(), planes.end());
        if (field == ggxcl::Field::u)
            floats.resize(floats.size() + (3 * CASE_COUNT - planes.size()), 0.0f);
    }
    for (const std::vector<float>& values : {backend.pdf(params, o), backend.eval(params, o)})
        floats.insert(floats.end(), values.begin(), values.end());
    return floats;
}

} // namespace

int main(int argc, char** argv)
{
    const bool vulkan = argc == 4 && std::string(argv[3]) == "vulkan";
    if (argc != 3 && !vulkan) {
        std::fprintf(stderr, "usage: cpp_dump OUT.f32 USER_SAMPLER_DIR [vulkan]\n");
        return 2;
    }
    std::unique_ptr<ggxcl::Backend> backend = ggxcl::open_backend(vulkan ? ggxcl::Api::vulkan : ggxcl::Api::opencl);
    std::FILE* file = std::fopen(argv[1], "wb");
    if (!file)
        return 1;
    for (const api_case& c : api_cases) {
        const ggxcl::SampleParams params = case_params(c, argv[2], vulkan);
        const std::vector<float> floats = vulkan ? dump_host_case(*backend, params)
                                                 : dump_case(static_cast<ggxcl::Sampler&>(*backend), params);
        if (floats.size() != CASE_FLOATS || std::fwrite(floats.data(), sizeof(float), floats.size(), file) != floats.size())
            return 1;
    }
    std::printf("cpp_dump: %zu cases on %s\n", CASE_TOTAL, backend->device_name().c_str());
    return std::fclose(file) == 0 ? 0 : 1;
}
