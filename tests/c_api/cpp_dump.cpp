// cpp_dump.cpp - what the C++ API's enqueue gives for the requests of
// c_api_cases.h: every method's six fields, then enqueue_pdf and
// enqueue_eval of the sampled o, written as raw floats to the file named
// by argv[1] (CASE_FLOATS per method, in id order) for c_consumer.c.
#include <cstdio>
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

// One method's floats: each field's planes packed CASE_COUNT apart.
std::vector<float> dump_method(ggxcl::Sampler& sampler, ggxcl::Method method)
{
    const int id = static_cast<int>(method);
    ggxcl::SampleParams params;
    params.method = method;
    params.alpha_x = case_alpha_x(id);
    params.alpha_y = case_alpha_y(id);
    params.view = {case_view[0], case_view[1], case_view[2]};
    cl::CommandQueue& queue = sampler.queue();
    ggxcl::DeviceOutputs out;
    for (ggxcl::Field field : ggxcl::all_fields)
        out.of(field) = cl::Buffer(sampler.context(), CL_MEM_READ_WRITE,
                                   sizeof(float) * 3 * CASE_STRIDE);
    sampler.enqueue(queue, params, {CASE_SEED, CASE_FIRST, CASE_COUNT}, out, CASE_STRIDE);
    cl::Buffer pdf(sampler.context(), CL_MEM_READ_WRITE, sizeof(float) * CASE_STRIDE);
    cl::Buffer value(sampler.context(), CL_MEM_READ_WRITE, sizeof(float) * CASE_STRIDE);
    sampler.enqueue_pdf(queue, params, CASE_COUNT, out.o, pdf, CASE_STRIDE);
    sampler.enqueue_eval(queue, params, CASE_COUNT, out.o, value, CASE_STRIDE);
    std::vector<float> floats;
    auto add = [&](const cl::Buffer& buffer, int planes) {
        const std::vector<float> host = read(queue, buffer, static_cast<std::size_t>(planes) * CASE_STRIDE);
        for (int c = 0; c < planes; ++c)
            floats.insert(floats.end(), host.begin() + c * CASE_STRIDE, host.begin() + c * CASE_STRIDE + CASE_COUNT);
    };
    for (ggxcl::Field field : ggxcl::all_fields)
        add(out.of(field), ggxcl::field_columns(field));
    add(pdf, 1);
    add(value, 1);
    return floats;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: cpp_dump OUT.f32\n");
        return 2;
    }
    ggxcl::Sampler sampler;
    std::FILE* file = std::fopen(argv[1], "wb");
    if (!file)
        return 1;
    for (ggxcl::Method method : ggxcl::all_methods) {
        const std::vector<float> floats = dump_method(sampler, method);
        if (floats.size() != CASE_FLOATS || std::fwrite(floats.data(), sizeof(float), floats.size(), file) != floats.size())
            return 1;
    }
    std::printf("cpp_dump: %zu methods on %s\n", ggxcl::all_methods.size(), sampler.device_name().c_str());
    return std::fclose(file) == 0 ? 0 : 1;
}
