// native_baseline.cpp - ggxnative::run: picks the loop of one (method, job), splits [0, count)
// into `threads` contiguous block-aligned ranges and runs them on std::threads.
#include <thread>
#include <vector>

#include "native_jobs.hpp"

namespace ggxnative {
namespace {

// The body of one thread: a job over a range; block_sums is used by furnace_sum only.
using RangeJob = void (*)(const Setup&, const Buffers&, Range, double* block_sums);

template <TangentSampler sample>
void write_job(const Setup& setup, const Buffers& buffers, Range range, double*)
{
    write_m_pdf_m<sample>(setup, buffers, range);
}

template <TangentSampler sample>
void furnace_job(const Setup& setup, const Buffers&, Range range, double* block_sums)
{
    furnace_sum<sample>(setup, range, block_sums);
}

template <WorldSampler sample_o>
void world_job(const Setup& setup, const Buffers& buffers, Range range, double*)
{
    world_space_o<sample_o>(setup, buffers, range);
}

template <TangentSampler sample>
RangeJob tangent_job(Job job)
{
    if (job == Job::write_m_pdf_m)
        return write_job<sample>;
    if (job == Job::furnace_sum)
        return furnace_job<sample>;
    return world_job<world_o_through_basis<sample>>;
}

RangeJob pick_job(Method method, Job job)
{
    switch (method) {
    case Method::ndf:
        return tangent_job<sample_ndf>(job);
    case Method::heitz:
        return tangent_job<sample_heitz>(job);
    case Method::heitz2017:
        return tangent_job<sample_heitz2017>(job);
    case Method::caps:
        return tangent_job<sample_caps>(job);
    case Method::caps_iso:
        return job == Job::world_space_o ? world_job<world_o_caps_iso> : tangent_job<sample_caps_iso_tangent>(job);
    case Method::bounded:
        return tangent_job<sample_bounded>(job);
    }
    return nullptr;
}

// Range t of `threads`, its ends rounded to whole furnace blocks.
Range thread_range(std::uint64_t count, int t, int threads)
{
    std::uint64_t blocks = (count + furnace_block - 1) / furnace_block;
    std::uint64_t first = blocks * std::uint64_t(t) / std::uint64_t(threads);
    std::uint64_t last = blocks * std::uint64_t(t + 1) / std::uint64_t(threads);
    std::uint64_t begin = first * furnace_block, end = last * furnace_block;
    return {begin < count ? begin : count, end < count ? end : count};
}

}  // namespace

double run(const Setup& setup, const Buffers& buffers)
{
    RangeJob job = pick_job(setup.method, setup.job);
    int threads = setup.threads < 1 ? 1 : setup.threads;
    std::vector<double> block_sums((setup.count + furnace_block - 1) / furnace_block, 0.0);
    std::vector<std::thread> workers;
    for (int t = 1; t < threads; ++t)
        workers.emplace_back(job, std::cref(setup), std::cref(buffers), thread_range(setup.count, t, threads),
                             block_sums.data());
    job(setup, buffers, thread_range(setup.count, 0, threads), block_sums.data());
    for (std::thread& worker : workers)
        worker.join();
    double total = 0.0;
    for (double sum : block_sums)
        total += sum;
    return setup.job == Job::furnace_sum ? total : 0.0;
}

const char* method_name(Method method)
{
    switch (method) {
    case Method::ndf:
        return "ndf";
    case Method::heitz:
        return "heitz";
    case Method::heitz2017:
        return "heitz2017";
    case Method::caps:
        return "caps";
    case Method::caps_iso:
        return "caps-iso";
    case Method::bounded:
        return "bounded";
    }
    return "?";
}

const char* job_name(Job job)
{
    switch (job) {
    case Job::write_m_pdf_m:
        return "write_m_pdf_m";
    case Job::furnace_sum:
        return "furnace_sum";
    case Job::world_space_o:
        return "world_space_o";
    }
    return "?";
}

}  // namespace ggxnative
