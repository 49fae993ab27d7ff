// native_timing.cpp - prints the native baseline's timing table: ns per sample, median of 5 runs
// of 2^22 samples (after a warm-up run), alpha 0.3, view at 60 degrees, 2 threads, for every
// method x job, and the hand-vectorized caps furnace ceiling.  Runs are interleaved across the
// cells (see main).
// Usage: native_timing [log2 count] [threads]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "native_baseline.hpp"

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

// Per-sample world-space inputs: normals uniform on the sphere, views at 60 degrees from them.
void world_inputs(std::uint64_t count, std::vector<float>& normals, std::vector<float>& views)
{
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    const double theta = 60.0 * pi / 180.0;
    for (std::uint64_t k = 0; k < count; ++k) {
        const double z = 1.0 - 2.0 * uni(rng), phi = 2.0 * pi * uni(rng), r = std::sqrt(1.0 - z * z);
        const double n[3] = {r * std::cos(phi), r * std::sin(phi), z};
        // Any unit tangent t of n, then b = n x t.
        double t[3] = {-n[1], n[0], 0.0};
        if (std::fabs(n[2]) > 0.9)
            t[0] = 0.0, t[1] = -n[2], t[2] = n[1];
        const double len = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        for (double& c : t)
            c /= len;
        const double b[3] = {n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]};
        const double psi = 2.0 * pi * uni(rng);
        for (int c = 0; c < 3; ++c) {
            normals[k + c * count] = float(n[c]);
            views[k + c * count] = float(std::cos(theta) * n[c] +
                                         std::sin(theta) * (std::cos(psi) * t[c] + std::sin(psi) * b[c]));
        }
    }
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
    world_inputs(count, normals, views);
    ggxnative::Buffers buffers;
    buffers.m = m.data(), buffers.pdf_m = pdf.data(), buffers.o = o.data();
    buffers.normals = normals.data(), buffers.views = views.data();

    const ggxnative::Method methods[] = {ggxnative::Method::ndf,      ggxnative::Method::heitz,
                                         ggxnative::Method::heitz2017, ggxnative::Method::caps,
                                         ggxnative::Method::caps_iso,  ggxnative::Method::bounded};
    const ggxnative::Job jobs[] = {ggxnative::Job::write_m_pdf_m, ggxnative::Job::furnace_sum,
                                   ggxnative::Job::world_space_o};
    // One timed run of each cell per round, 5 rounds after a warm-up round: interleaving spreads
    // any slow period of a shared machine over all cells instead of spoiling one.
    std::vector<std::vector<double>> ns(6 * 3 + 1);
    for (int round = 0; round <= 5; ++round) {
        const std::uint64_t seed = 1000 + std::uint64_t(round);
        for (int mi = 0; mi < 6; ++mi)
            for (int ji = 0; ji < 3; ++ji) {
                ggxnative::Setup setup{methods[mi], jobs[ji], 0.3f, 0.3f, {view[0], view[1], view[2]}, seed, count, threads};
                double t = ns_per_sample([&] { ggxnative::run(setup, buffers); }, count);
                if (round > 0)
                    ns[std::size_t(mi * 3 + ji)].push_back(t);
            }
        double t = ns_per_sample([&] { ggxnative::furnace_caps_vectorized(seed, count, 0.3f, view, threads); }, count);
        if (round > 0)
            ns.back().push_back(t);
    }

    std::printf("2^%d samples, alpha 0.3, view at 60 degrees, %d threads; ns per sample, median of 5 runs\n\n",
                log2_count, threads);
    std::printf("| method | write_m_pdf_m | furnace_sum | world_space_o |\n|---|---|---|---|\n");
    for (int mi = 0; mi < 6; ++mi) {
        std::printf("| %s |", ggxnative::method_name(methods[mi]));
        for (int ji = 0; ji < 3; ++ji)
            std::printf(" %.2f |", median(ns[std::size_t(mi * 3 + ji)]));
        std::printf("\n");
    }
    std::printf("| caps, hand-vectorized ceiling | | %.2f | |\n", median(ns.back()));
    return 0;
}
