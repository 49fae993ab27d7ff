// native_timing.cpp - prints the native baseline's timing table: ns per sample, median of 5 runs
// of 2^22 samples (after a warm-up run), alpha 0.3, view at 60 degrees, 2 threads, for every
// method x job, and each method's furnace job vectorized by the compiler.  Runs are interleaved across the
// cells (see main).
// Usage: native_timing [log2 count] [threads]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "native_baseline.hpp"
#include "native_world_inputs.hpp"

namespace {

constexpr double pi = 3.14159265358979323846;

using Clock = std::chrono::steady_clock;

template <class F>
double ns_per_sample(F run_once, std::uint64_t count)
{
    Clock::time_point start = Clock::now();
    run_once();
    return std::chrono::duration<double, std::nano>(Clock::now() - start).count() / double(count);
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv)
{
    const int log2_count = argc > 1 ? std::atoi(argv[1]) : 22;
    const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
    const std::uint64_t count = std::uint64_t(1) << log2_count;
    const double theta = 60.0 * pi / 180.0;
    const float view[3] = {float(std::sin(theta)), 0.0f, float(std::cos(theta))};
    std::vector<float> m(3 * count), pdf(count), o(3 * count), normals(3 * count), views(3 * count);
    ggxnative::world_inputs(count, normals, views);
    ggxnative::Buffers buffers;
    buffers.m = m.data(), buffers.pdf_m = pdf.data(), buffers.o = o.data();
    buffers.normals = normals.data(), buffers.views = views.data();

    const int methods = ggxnative::method_count();
    const ggxnative::Job jobs[] = {ggxnative::Job::write_m_pdf_m, ggxnative::Job::furnace_sum,
                                   ggxnative::Job::world_space_o};
    // One timed run of each cell per round, 5 rounds after a warm-up round: interleaving spreads
    // any slow period of a shared machine over all cells instead of spoiling one.  Column 3 of a
    // method is its furnace job vectorized by the compiler.
    std::vector<std::vector<double>> ns(std::size_t(methods) * 4);
    for (int round = 0; round <= 5; ++round) {
        const std::uint64_t seed = 1000 + std::uint64_t(round);
        for (int mi = 0; mi < methods; ++mi)
            for (int ji = 0; ji < 4; ++ji) {
                ggxnative::Setup setup{mi, jobs[ji < 3 ? ji : 1], 0.3f, 0.3f, {view[0], view[1], view[2]}, seed, count,
                                       threads};
                double t = ns_per_sample([&] { ji < 3 ? ggxnative::run(setup, buffers) : ggxnative::furnace_vectorized(setup); },
                                         count);
                if (round > 0)
                    ns[std::size_t(mi * 4 + ji)].push_back(t);
            }
    }

    std::printf("2^%d samples, alpha 0.3, view at 60 degrees, %d threads; ns per sample, median of 5 runs\n\n",
                log2_count, threads);
    std::printf("| method | write_m_pdf_m | furnace_sum | world_space_o | furnace_sum, omp simd |\n|---|---|---|---|---|\n");
    for (int mi = 0; mi < methods; ++mi) {
        std::printf("| %s |", ggxnative::method_name(mi));
        for (int ji = 0; ji < 4; ++ji)
            std::printf(" %.2f |", median(ns[std::size_t(mi * 4 + ji)]));
        std::printf("\n");
    }
    return 0;
}
