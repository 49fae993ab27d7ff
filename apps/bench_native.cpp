// bench_native.cpp - timings and error of the native C++ baseline.
#include "bench_native.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <vector>

#include "native_baseline.hpp"
#include "reference_bridge.hpp"

namespace ggxapp {

namespace {

ggxnative::Method native_method(ggxcl::Method method)
{
    return static_cast<ggxnative::Method>(int(reference_method(method)));  // same order as ggxref::Method
}

ggxnative::Job native_job(BenchJob job)
{
    switch (job) {
    case BenchJob::write: return ggxnative::Job::write_m_pdf_m;
    case BenchJob::furnace: return ggxnative::Job::furnace_sum;
    case BenchJob::world: return ggxnative::Job::world_space_o;
    }
    return ggxnative::Job::write_m_pdf_m;
}

// Wall-clock ns per sample of `run`, median of `repeats` after one warm-up.
Timing wall_timing(const std::function<void(std::uint64_t seed)>& run, std::uint32_t count, int repeats)
{
    run(1);
    std::vector<double> ns;
    for (int r = 0; r < repeats; ++r) {
        auto start = std::chrono::steady_clock::now();
        run(std::uint64_t(r) + 2);
        std::chrono::duration<double, std::nano> elapsed = std::chrono::steady_clock::now() - start;
        ns.push_back(elapsed.count() / count);
    }
    return summarize(ns);
}

} // namespace

Timing native_timing(ggxcl::Method method, BenchJob job, const NativeSetup& setup)
{
    const std::size_t n = setup.count;
    std::vector<float> m, pdf_m, o, normals, views;
    if (job == BenchJob::write) {
        m.resize(3 * n);
        pdf_m.resize(n);
    }
    if (job == BenchJob::world) {
        o.resize(3 * n);
        random_world_inputs(setup.count, normals, views);
    }
    ggxnative::Buffers buffers{m.data(), pdf_m.data(), o.data(), normals.data(), views.data()};
    auto run = [&](std::uint64_t seed) {
        ggxnative::Setup s{native_method(method), native_job(job), setup.alpha, setup.alpha,
                           {setup.view.x, setup.view.y, setup.view.z}, seed, n, setup.threads};
        ggxnative::run(s, buffers);
    };
    return wall_timing(run, setup.count, setup.repeats);
}

Timing native_ceiling_timing(const NativeSetup& setup)
{
    float view[3] = {setup.view.x, setup.view.y, setup.view.z};
    auto run = [&](std::uint64_t seed) {
        ggxnative::furnace_caps_vectorized(seed, setup.count, setup.alpha, view, setup.threads);
    };
    return wall_timing(run, setup.count, setup.repeats);
}

NumericalError native_numerical_error(ggxcl::Method method)
{
    const std::uint64_t count = accuracy_samples;
    std::vector<double> angles, pdfs;
    NumericalError error;
    for (const ggxcl::SampleParams& p : accuracy_configs(method, ggxcl::Precision::precise)) {
        std::vector<float> m(3 * count), pdf_m(count);
        ggxnative::run({native_method(method), ggxnative::Job::write_m_pdf_m, p.alpha_x, p.alpha_y,
                        {p.view.x, p.view.y, p.view.z}, accuracy_seed, count, 1},
                       {m.data(), pdf_m.data()});
        ggxref::Params ref = reference_params(p);
        for (std::uint64_t j = 0; j < count; ++j) {
            std::array<double, 2> u = ggxref::uniforms(accuracy_seed, j);
            ggxref::Sample r = ggxref::sample(reference_method(method), ref, u[0], u[1]);
            double angle = angle_between({m[j], m[count + j], m[2 * count + j]}, r.m);
            if (!std::isfinite(angle) || !std::isfinite(pdf_m[j])) {
                ++error.non_finite;
                continue;
            }
            angles.push_back(angle);
            pdfs.push_back(relative_error(pdf_m[j], r.pdf_m));
        }
    }
    percentiles(angles, error.angle_p99, error.angle_max);
    percentiles(pdfs, error.pdf_p99, error.pdf_max);
    return error;
}

} // namespace ggxapp
