// bench_enqueue.cpp - host time of small enqueues (see bench_enqueue.hpp).
#include "bench_enqueue.hpp"

#include <chrono>

namespace ggxapp {

namespace {

double microseconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

EnqueueTiming measure_enqueue(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params)
{
    EnqueueTiming result;
    result.measured = true;
    const std::uint32_t count = result.count;
    cl::CommandQueue queue(sampler.context(), sampler.device());
    ggxcl::DeviceOutputs out;
    out.m = cl::Buffer(sampler.context(), CL_MEM_WRITE_ONLY, 3 * count * sizeof(float));
    out.pdf_m = cl::Buffer(sampler.context(), CL_MEM_WRITE_ONLY, count * sizeof(float));
    sampler.warm_up(params, {ggxcl::Field::m, ggxcl::Field::pdf_m});
    std::vector<double> us;
    for (int call = 0; call < result.calls; ++call) {
        auto start = std::chrono::steady_clock::now();
        sampler.enqueue(queue, params, {1, std::uint64_t(call) * count, count}, out);
        us.push_back(microseconds_since(start));
        queue.finish();
    }
    result.host_us = summarize(us);
    ggxcl::Sampler second(sampler.context(), sampler.device());
    auto start = std::chrono::steady_clock::now();
    second.enqueue(queue, params, {1, 0, count}, out);
    result.second_sampler_first_us = microseconds_since(start);
    queue.finish();
    return result;
}

} // namespace ggxapp
