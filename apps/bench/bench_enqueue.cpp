// bench_enqueue.cpp - host time of small enqueues (see bench_enqueue.hpp).
#include "bench_enqueue.hpp"

#include <chrono>

namespace ggxapp {

namespace {

double microseconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
}

// Enqueue + finish into buffers with room for the odd offset, at 0 and at the offset in turn.
void measure_offsets(ggxcl::Sampler& sampler, cl::CommandQueue& queue, const ggxcl::SampleParams& params,
                     EnqueueTiming& result)
{
    const std::uint64_t count = result.count, at = result.odd_offset;
    ggxcl::DeviceOutputs out;
    out.m = cl::Buffer(sampler.context(), CL_MEM_WRITE_ONLY, (3 * count + at) * sizeof(float));
    out.pdf_m = cl::Buffer(sampler.context(), CL_MEM_WRITE_ONLY, (count + at) * sizeof(float));
    std::vector<double> at_zero, at_odd;
    for (int call = 0; call < 2 * result.calls; ++call) {
        const bool odd = call % 2 == 1;
        out.m_offset = out.pdf_m_offset = odd ? at : 0;
        auto start = std::chrono::steady_clock::now();
        sampler.enqueue(queue, params, {1, std::uint64_t(call) * count, count}, out);
        queue.finish();
        (odd ? at_odd : at_zero).push_back(microseconds_since(start));
    }
    result.at_zero_us = summarize(at_zero);
    result.at_odd_offset_us = summarize(at_odd);
}

EnqueueTiming enqueue_timing(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params)
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
    measure_offsets(sampler, queue, params, result);
    return result;
}

} // namespace

EnqueueTiming measure_enqueue(const std::vector<ApiChoice>& apis, const ggxcl::SampleParams& params)
{
    for (const ApiChoice& choice : apis)  // Sampler::enqueue: the caller's buffers are OpenCL's
        if (choice.api == ggxcl::Api::opencl) {
            ggxcl::Sampler sampler(choice.selector);
            return enqueue_timing(sampler, params);
        }
    return {};
}

} // namespace ggxapp
