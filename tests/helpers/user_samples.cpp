// user_samples.cpp - a user kernel over the device headers, and the same
// samples through Sampler::enqueue, both as 9 planes.
#include "user_samples.hpp"

namespace ggxtest {

namespace {

constexpr int planes = 9;

const char* user_kernel = R"CL(
// Sample first + j of stream `seed` as a user kernel draws it: the uniforms
// of ggx_philox.h, then the sampler of `method` (ggx_samplers.h).
__kernel void user_samples(ulong seed, ulong first, uint count, int method, float ix, float iy, float iz,
                           float ax, float ay, float nx, float ny, float nz, __global float* out)
{
    uint j = get_global_id(0);
    float u1, u2;
    ggx_uniforms(seed, first + j, &u1, &u2);
    ggx_sample s = ggx_sample_method(method, ggx_vec3_make(nx, ny, nz), ggx_vec3_make(ix, iy, iz), ax, ay, u1, u2);
    float v[9] = {s.m.x, s.m.y, s.m.z, s.o.x, s.o.y, s.o.z, s.pdf_m, s.pdf_o, s.weight};
    for (int k = 0; k < 9; ++k)
        out[k * count + j] = v[k];
}
)CL";

std::vector<float> read_floats(cl::CommandQueue& queue, const cl::Buffer& buffer, std::size_t count)
{
    std::vector<float> host(count);
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, count * sizeof(float), host.data());
    return host;
}

} // namespace

std::string user_samples_source(bool include_header)
{
    return (include_header ? "#include \"ggx_samplers.h\"\n" : "\n") + std::string(user_kernel);
}

SamplePlanes run_user_samples(ggxcl::Sampler& sampler, const cl::Program& program, const ggxcl::SampleParams& params,
                              const ggxcl::SampleRange& range)
{
    const ggxcl::SampleParams p = ggxcl::normalized(params);
    cl::Buffer out(sampler.context(), CL_MEM_WRITE_ONLY, planes * range.count * sizeof(float));
    cl::Kernel kernel(program, "user_samples");
    kernel.setArg(0, cl_ulong(range.seed));
    kernel.setArg(1, cl_ulong(range.first));
    kernel.setArg(2, cl_uint(range.count));
    kernel.setArg(3, cl_int(static_cast<int>(p.method)));
    const float values[] = {p.view.x, p.view.y, p.view.z, p.alpha_x, p.alpha_y, p.normal.x, p.normal.y, p.normal.z};
    for (int k = 0; k < 8; ++k)
        kernel.setArg(4 + k, values[k]);
    kernel.setArg(12, out);
    sampler.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(range.count));
    return read_floats(sampler.queue(), out, planes * range.count);
}

PendingSamples start_samples(ggxcl::Sampler& sampler, cl::CommandQueue queue, const ggxcl::SampleParams& params,
                             const ggxcl::SampleRange& range)
{
    const cl::Context& context = sampler.context();
    const std::size_t bytes = range.count * sizeof(float);
    PendingSamples pending{queue, {}, range.count};
    pending.outputs.m = cl::Buffer(context, CL_MEM_WRITE_ONLY, 3 * bytes);
    pending.outputs.o = cl::Buffer(context, CL_MEM_WRITE_ONLY, 3 * bytes);
    pending.outputs.pdf_m = cl::Buffer(context, CL_MEM_WRITE_ONLY, bytes);
    pending.outputs.pdf_o = cl::Buffer(context, CL_MEM_WRITE_ONLY, bytes);
    pending.outputs.weight = cl::Buffer(context, CL_MEM_WRITE_ONLY, bytes);
    sampler.enqueue(pending.queue, params, range, pending.outputs);
    return pending;
}

SamplePlanes finish_samples(PendingSamples& pending)
{
    SamplePlanes all;
    const ggxcl::DeviceOutputs& out = pending.outputs;
    for (const cl::Buffer* buffer : {&out.m, &out.o, &out.pdf_m, &out.pdf_o, &out.weight}) {
        const std::size_t floats = (buffer == &out.m || buffer == &out.o ? 3 : 1) * pending.count;
        std::vector<float> part = read_floats(pending.queue, *buffer, floats);
        all.insert(all.end(), part.begin(), part.end());
    }
    return all;
}

SamplePlanes enqueue_samples(ggxcl::Sampler& sampler, cl::CommandQueue& queue, const ggxcl::SampleParams& params,
                             const ggxcl::SampleRange& range)
{
    PendingSamples pending = start_samples(sampler, queue, params, range);
    return finish_samples(pending);
}

SamplePlanes join_planes(const SamplePlanes& first, const SamplePlanes& second)
{
    const std::size_t n1 = first.size() / planes, n2 = second.size() / planes;
    SamplePlanes joined;
    for (int k = 0; k < planes; ++k) {
        joined.insert(joined.end(), first.begin() + k * n1, first.begin() + (k + 1) * n1);
        joined.insert(joined.end(), second.begin() + k * n2, second.begin() + (k + 1) * n2);
    }
    return joined;
}

} // namespace ggxtest
