// consumer.cpp - the smallest program built against ggxcl from outside the
// project (through pkg-config, or through the build tree's CMake export):
// its own context and queue, samples into its own buffer, and its own
// kernel including the device headers; prints "consumer ok" when the
// kernel's weights equal the runtime's.  It defines nothing for the OpenCL
// C++ bindings: the ggxcl headers turn their exceptions on, so a failed call
// of the bindings throws cl::Error here as in the library.
#include <cstdio>
#include <cstring>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace {

const char* user_kernel = R"CL(
#include "ggx_samplers.h"
__kernel void weights(ulong seed, float ix, float iz, float alpha, __global float* out)
{
    uint j = get_global_id(0);
    float u1, u2;
    ggx_uniforms(seed, j, &u1, &u2);
    out[j] = ggx_sample_caps(ggx_vec3_make(ix, 0.0f, iz), alpha, alpha, u1, u2).weight;
}
)CL";

constexpr std::size_t count = 4096;

std::vector<float> read(cl::CommandQueue& queue, const cl::Buffer& buffer)
{
    std::vector<float> host(count);
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, count * sizeof(float), host.data());
    return host;
}

} // namespace

int main()
{
    try {
        const cl::Device device = ggxcl::select_device().device;
        cl::Context context(device);
        cl::CommandQueue queue(context, device);
        ggxcl::Sampler sampler(context, device);
        ggxcl::SampleParams params{ggxcl::Method::caps, 0.4f, 0.4f, ggxcl::Vec3{0.6f, 0.0f, 0.8f}};
        ggxcl::DeviceOutputs outputs;
        outputs.weight = cl::Buffer(context, CL_MEM_WRITE_ONLY, count * sizeof(float));
        sampler.enqueue(queue, params, {9, 0, count}, outputs);

        cl::Buffer mine(context, CL_MEM_WRITE_ONLY, count * sizeof(float));
        cl::Kernel kernel(ggxcl::build_user_program(context, device, user_kernel), "weights");
        const ggxcl::Vec3 view = ggxcl::normalized(params).view;  // the unit view the runtime uses
        kernel.setArg(0, cl_ulong(9));
        kernel.setArg(1, view.x);
        kernel.setArg(2, view.z);
        kernel.setArg(3, 0.4f);
        kernel.setArg(4, mine);
        queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(count));
        bool threw = false;
        try {
            cl::Buffer empty(context, CL_MEM_READ_WRITE, 0);  // CL_INVALID_BUFFER_SIZE
        } catch (const cl::Error&) {
            threw = true;
        }
        if (!threw) {
            std::fprintf(stderr, "consumer: the bindings did not throw: built without exceptions\n");
            return 1;
        }
        const bool same = read(queue, mine) == read(queue, outputs.weight);
        std::printf("consumer %s: ggxcl %s, device headers %s\n", same ? "ok" : "MISMATCH", ggxcl::version(),
                    ggxcl::device_include_dir().c_str());
        return same ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "consumer: %s\n", e.what());
        return 1;
    }
}
