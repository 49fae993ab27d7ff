// enqueue_threads.cpp - small-batch launches from several threads sharing
// one Sampler, each thread on its own queue (docs/PIPELINES.md): for 1, 2,
// 4 and 8 threads, the host time of one enqueue call (median over every
// call) and the launches per second of all threads together (median of 5
// runs).  Each call draws `count` caps samples (m and pdf_m) into the
// thread's own buffers; each thread waits for its queue every 32 calls.
// Usage: enqueue_threads [CALLS_PER_THREAD (2000)] [COUNT (256)]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// One thread's calls; returns the host microseconds of each.
std::vector<double> launch_calls(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params, int calls,
                                 std::uint32_t count)
{
    cl::CommandQueue queue(sampler.context(), sampler.device());
    ggxcl::DeviceOutputs out;
    out.m = cl::Buffer(sampler.context(), CL_MEM_WRITE_ONLY, 3 * count * sizeof(float));
    out.pdf_m = cl::Buffer(sampler.context(), CL_MEM_WRITE_ONLY, count * sizeof(float));
    std::vector<double> us;
    for (int call = 0; call < calls; ++call) {
        auto start = Clock::now();
        sampler.enqueue(queue, params, {1, std::uint64_t(call) * count, count}, out);
        us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
        if (call % 32 == 31)
            queue.finish();
    }
    queue.finish();
    return us;
}

struct Run {
    double launches_per_s, call_us;
};

Run run_threads(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params, int threads, int calls,
                std::uint32_t count)
{
    std::vector<std::vector<double>> us(threads);
    auto start = Clock::now();
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] { us[t] = launch_calls(sampler, params, calls, count); });
    for (std::thread& thread : pool)
        thread.join();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    std::vector<double> all;
    for (const auto& one : us)
        all.insert(all.end(), one.begin(), one.end());
    return {threads * calls / seconds, median(all)};
}

} // namespace

int main(int argc, char** argv)
{
    const int calls = argc > 1 ? std::atoi(argv[1]) : 2000;
    const std::uint32_t count = argc > 2 ? std::uint32_t(std::atoi(argv[2])) : 256;
    ggxcl::Sampler sampler;
    ggxcl::SampleParams params{ggxcl::Method::caps, 0.3f, 0.3f, ggxcl::view_from_angles(60, 0)};
    sampler.warm_up(params, {ggxcl::Field::m, ggxcl::Field::pdf_m});
    std::printf("# %s: %d calls of %u samples per thread, medians of 5 runs\n", sampler.device_name().c_str(), calls,
                count);
    std::printf("threads,launches_per_s,enqueue_call_us\n");
    for (int threads : {1, 2, 4, 8}) {
        std::vector<double> rates, call_us;
        run_threads(sampler, params, threads, calls / 4, count);  // each thread's first lease of the variant
        for (int r = 0; r < 5; ++r) {
            Run run = run_threads(sampler, params, threads, calls, count);
            rates.push_back(run.launches_per_s);
            call_us.push_back(run.call_us);
        }
        std::printf("%d,%.0f,%.1f\n", threads, median(rates), median(call_us));
    }
}
