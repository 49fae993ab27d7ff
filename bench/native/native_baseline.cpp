// native_baseline.cpp - ggxnative::run: picks the loop of one (method, job), splits [0, count)
// into `threads` contiguous block-aligned ranges and runs them on std::threads; method names
// from the project's list of methods.
#include <thread>
#include <vector>

#include "native_jobs.hpp"

namespace ggxnative {
namespace {

// The body of one thread: a job over a range; block_sums is used by furnace_sum only.
using RangeJob = void (*)(const Setup&, const Buffers&, Range, double* block_sums);

template <int method>
void write_job(const Setup& setup, const Buffers& buffers, Range range, double*)
{
    write_m_pdf_m<method>(setup, buffers, range);
}

template <int method>
void furnace_job(const Setup& setup, const Buffers&, Range range, double* block_sums)
{
    furnace_sum<method>(setup, range, block_sums);
}

template <int method>
void world_job(const Setup& setup, const Buffers& buffers, Range range, double*)
{
    world_space_o<method>(setup, buffers, range);
}

template <int method>
RangeJob job_of(Job job)
{
    if (job == Job::write_m_pdf_m)
        return write_job<method>;
    if (job == Job::furnace_sum)
        return furnace_job<method>;
    return world_job<method>;
}

RangeJob pick_job(int method, Job job)
{
    switch (method) {
#define GGXNATIVE_JOB_OF(ID, identifier, name, ...) \
    case GGX_METHOD_##ID:                      \
        return job_of<GGX_METHOD_##ID>(job);
        GGX_METHOD_LIST(GGXNATIVE_JOB_OF)
#undef GGXNATIVE_JOB_OF
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

const char* const method_names[] = {
#define GGXNATIVE_NAME(ID, identifier, name, ...) name,
    GGX_METHOD_LIST(GGXNATIVE_NAME)
#undef GGXNATIVE_NAME
};

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

int method_count() { return GGX_METHOD_COUNT; }

const char* method_name(int method)
{
    return method >= 0 && method < GGX_METHOD_COUNT ? method_names[method] : "?";
}

int method_id(const std::string& name)
{
    for (int method = 0; method < GGX_METHOD_COUNT; ++method)
        if (name == method_names[method])
            return method;
    return -1;
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
