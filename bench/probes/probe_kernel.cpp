// probe_kernel.cpp - times small probe kernels that isolate one cost of a
// bulk kernel (stores, Philox, one sampler's math): each .cl file defines
// `k(__global float* out, uint count)` and is built after ggx_samplers.h
// with the default (precise) build. Prints the median ns per work-item over 7 runs of
// 2^24 work-items (after one warm-up run), each probe in the same process.
// Usage: probe_kernel FILE.cl...
#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>

#include <ggxcl/ggxcl.hpp>

namespace {

double median_ns(ggxcl::Sampler& s, const std::string& source, cl::Buffer& out, cl_uint n)
{
    cl::Program program(s.context(), ggxcl::kernel_source("ggx_samplers.h") + source);
    program.build({s.device()});
    cl::Kernel k(program, "k");
    k.setArg(0, out);
    k.setArg(1, n);
    std::vector<double> ns;
    for (int r = 0; r < 8; ++r) {
        cl::Event done;
        s.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n), cl::NDRange(256), nullptr, &done);
        done.wait();
        if (r > 0)  // the first run JIT-compiles the kernel
            ns.push_back(double(done.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                                done.getProfilingInfo<CL_PROFILING_COMMAND_START>()) / n);
    }
    std::sort(ns.begin(), ns.end());
    return ns[ns.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::cerr << "usage: probe_kernel FILE.cl...\n";
        return 2;
    }
    ggxcl::Sampler s;
    const cl_uint n = 1u << 24;
    cl::Buffer out(s.context(), CL_MEM_READ_WRITE, 4ull * n * sizeof(float));
    for (int a = 1; a < argc; ++a) {
        std::ifstream in(argv[a]);
        std::stringstream text;
        text << in.rdbuf();
        std::cout << argv[a] << ": " << median_ns(s, text.str(), out, n) << " ns per work-item\n";
    }
    return 0;
}
