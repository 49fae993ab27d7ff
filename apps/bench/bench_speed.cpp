// bench_speed.cpp - device timings of the bench jobs: event-profiled, or
// wall clock when the profiling timestamps cannot be right.
#include "bench_speed.hpp"

#include "report_text.hpp"

#include <ggxcl/benchmark.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <sstream>

namespace ggxapp {

namespace {

constexpr std::uint32_t world_count_limit = 1u << 22;

// The store job's kernel: the write job's bytes (three planes of m, one of
// pdf_m) from values that cost nothing to compute.
const char* store_source = R"CL(
__kernel void store_only(__global float* restrict m, __global float* restrict pdf_m, uint count, float seed)
{
    uint j = get_global_id(0);
    float x = (float)j * 1e-7f + seed;
    m[j] = x;
    m[j + count] = x + 1.0f;
    m[j + 2 * count] = x + 2.0f;
    pdf_m[j] = x + 3.0f;
}
)CL";

cl::Buffer device_copy(ggxcl::Sampler& sampler, std::vector<float>& host)
{
    return cl::Buffer(sampler.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, host.size() * sizeof(float),
                      host.data());
}

// The profiled duration of a finished command in ns; -1 when the driver gives none.
double profiled_ns(const cl::Event& done)
{
    cl_ulong start = 0, end = 0;
    if (done.getProfilingInfo(CL_PROFILING_COMMAND_START, &start) != CL_SUCCESS ||
        done.getProfilingInfo(CL_PROFILING_COMMAND_END, &end) != CL_SUCCESS)
        return -1.0;
    return double(end) - double(start);
}

// Whether a profiled duration can be the kernel time of a run that took
// `wall_ns` from launch to finish: positive, at least 1% of it (some drivers
// return constant or zero timestamps), and not longer than it by more than
// timer slack.  A bench keeps the profiled times when most runs pass.
bool plausible_profile(double event_ns, double wall_ns)
{
    return event_ns > 0.0 && event_ns >= 0.01 * wall_ns && event_ns <= 1.5 * wall_ns + 1e6;
}

std::string describe_implausible(double event_ns, double wall_ns)
{
    return "a run profiled at " + duration_text(event_ns) + " took " + duration_text(wall_ns);
}

} // namespace

void random_world_inputs(std::uint32_t count, std::vector<float>& normals, std::vector<float>& views)
{
    std::mt19937 rng(20231122);
    std::normal_distribution<float> gauss;
    normals.resize(3 * std::size_t(count));
    views.resize(3 * std::size_t(count));
    for (std::uint32_t j = 0; j < count; ++j) {
        float n[3], v[3];
        do {
            for (float& c : n) c = gauss(rng);
            float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (float& c : n) c /= len;
        } while (n[2] < -0.999f);
        float along;
        do {
            for (float& c : v) c = gauss(rng);
            float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            for (float& c : v) c /= len;
            along = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
            if (along < 0.0f)
                for (int c = 0; c < 3; ++c) v[c] -= 2.0f * along * n[c];  // mirror into the upper side
            along = std::fabs(along);
        } while (along < 0.05f);
        for (int c = 0; c < 3; ++c) {
            normals[c * std::size_t(count) + j] = n[c];
            views[c * std::size_t(count) + j] = v[c];
        }
    }
}

std::string job_name(BenchJob job)
{
    switch (job) {
    case BenchJob::write: return "write";
    case BenchJob::write_o: return "write-o";
    case BenchJob::furnace: return "furnace";
    case BenchJob::world: return "world";
    case BenchJob::per_sample: return "per-sample";
    case BenchJob::store: return "store";
    }
    return "?";
}

Timing summarize(std::vector<double> ns)
{
    std::sort(ns.begin(), ns.end());
    return {ns[ns.size() / 2], ns.front(), ns.back()};
}

double wall_ns_per_sample(const std::function<void()>& call, std::uint64_t count)
{
    const auto start = std::chrono::steady_clock::now();
    call();
    return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / double(count);
}

DeviceTimer::DeviceTimer(ggxcl::Sampler& sampler, std::uint32_t count)
    : sampler_(sampler), count_(count), world_count_(std::min(count, world_count_limit))
{
    const cl::Context& context = sampler.context();
    write_out_.m = cl::Buffer(context, CL_MEM_WRITE_ONLY, 3 * std::size_t(count) * sizeof(float));
    write_out_.pdf_m = cl::Buffer(context, CL_MEM_WRITE_ONLY, std::size_t(count) * sizeof(float));
    world_out_.o = cl::Buffer(context, CL_MEM_WRITE_ONLY, 3 * std::size_t(world_count_) * sizeof(float));
    write_o_out_.o = write_out_.m;  // the same bytes: 3 planes and 1
    write_o_out_.pdf_o = write_out_.pdf_m;
    // Weights and their squares, and a dielectric's reflected weights (Sampler::enqueue_furnace).
    sums_ = cl::Buffer(context, CL_MEM_WRITE_ONLY, 3 * sampler.furnace_items(count) * sizeof(float));
    std::vector<float> normals, views;
    random_world_inputs(world_count_, normals, views);
    world_in_.normal = device_copy(sampler, normals);
    world_in_.view = device_copy(sampler, views);
    world_in_.views_above_horizon = true;  // true by construction
    world_in_.isotropic = true;
    std::vector<float> alphas(2 * std::size_t(world_count_));
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> alpha(0.05f, 1.0f);
    for (float& a : alphas)
        a = alpha(rng);
    for (std::uint32_t j = 0; j < world_count_; ++j)  // the views of the world job, read as tangent-space views
        if (views[2 * std::size_t(world_count_) + j] < 0.0f)
            views[2 * std::size_t(world_count_) + j] = -views[2 * std::size_t(world_count_) + j];
    per_sample_in_.view = device_copy(sampler, views);
    per_sample_in_.alpha = device_copy(sampler, alphas);
    per_sample_in_.views_above_horizon = true;
    cl::Program store(context, store_source);
    store.build({sampler.device()});
    store_ = cl::Kernel(store, "store_only");
}

std::uint32_t DeviceTimer::count_of(BenchJob job) const
{
    return job == BenchJob::world || job == BenchJob::per_sample ? world_count_ : count_;
}

cl::Event DeviceTimer::launch(const BenchTask& task, std::uint64_t seed)
{
    cl::CommandQueue& queue = sampler_.queue();
    const ggxcl::SampleParams& params = task.params;
    switch (task.job) {
    case BenchJob::write:  // with or without the guards (params.guards)
        return sampler_.enqueue(queue, params, {seed, 0, count_}, write_out_);
    case BenchJob::write_o:
        return sampler_.enqueue(queue, params, {seed, 0, count_}, write_o_out_);
    case BenchJob::furnace: {  // as Sampler::furnace runs it: unguarded, rerun with guards only on a NaN sum
        ggxcl::SampleParams unguarded = params;
        unguarded.guards = false;
        return sampler_.enqueue_furnace(queue, unguarded, {seed, 0, count_}, sums_);
    }
    case BenchJob::world: {
        ggxcl::SampleParams world = params;
        world.world_space = true;
        world.alpha_y = world.alpha_x;
        return sampler_.enqueue(queue, world, {seed, 0, world_count_}, world_out_, 0, world_in_);
    }
    case BenchJob::per_sample:
        return sampler_.enqueue(queue, params, {seed, 0, world_count_}, write_out_, 0, per_sample_in_);
    case BenchJob::store: {
        store_.setArg(0, write_out_.m);
        store_.setArg(1, write_out_.pdf_m);
        store_.setArg(2, cl_uint(count_));
        store_.setArg(3, cl_float(seed));
        cl::Event done;
        queue.enqueueNDRangeKernel(store_, cl::NullRange, cl::NDRange(count_), cl::NullRange, nullptr, &done);
        return done;
    }
    }
    return {};
}

std::vector<Timing> DeviceTimer::time_interleaved(const std::vector<BenchTask>& tasks, int repeats)
{
    for (const BenchTask& task : tasks)
        launch(task, 1).wait();  // warm-up: build and JIT
    std::vector<std::vector<double>> profiled(tasks.size()), wall(tasks.size());
    // Broken timestamps fail every run; a loaded machine only delays some
    // launches past 100x their kernel (small runs): the majority decides.
    int implausible = 0, runs = 0;
    for (int r = 0; r < repeats; ++r)
        for (std::size_t t = 0; t < tasks.size(); ++t) {
            auto start = std::chrono::steady_clock::now();
            cl::Event done = launch(tasks[t], std::uint64_t(r) + 2);
            done.wait();
            const double wall_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
            const double event_ns = profiled_ns(done);
            ++runs;
            if (!plausible_profile(event_ns, wall_ns) && implausible++ == 0)
                plausible_note_ = describe_implausible(event_ns, wall_ns);
            profiled[t].push_back(event_ns / count_of(tasks[t].job));
            wall[t].push_back(wall_ns / count_of(tasks[t].job));
        }
    const bool plausible = 2 * implausible <= runs;
    if (!plausible)
        plausible_note_ += " (" + std::to_string(implausible) + " of " + std::to_string(runs) + " runs implausible)";
    wall_clock_ = !plausible;
    std::vector<Timing> timings;
    for (std::vector<double>& samples : plausible ? profiled : wall)
        timings.push_back(summarize(samples));
    return timings;
}

std::string DeviceTimer::clock_description() const
{
    if (!wall_clock_)
        return "event-profiled";
    return "wall-clock (launch to finish: the device's profiling timestamps cannot be right, " + plausible_note_ + ")";
}

} // namespace ggxapp
