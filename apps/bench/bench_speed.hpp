// bench_speed.hpp - the device timings of `ggx bench`: the library's jobs
// (ggxcl::benchmark::DeviceJobs: write, write-o, furnace, world,
// per-sample, store; what each draws and writes is said there) on every
// device of the run, each the median of repeated runs after a warm-up run
// (which builds and compiles the variant), all devices' tasks in the same
// interleaved rounds.  A device's rows are timed by the API's profiling
// (OpenCL events) unless its runs gave none or any of them cannot be right,
// and then by wall clock, for every row of that device alike.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <ggxcl/benchmark.hpp>
#include <ggxcl/ggxcl.hpp>

#include "api_options.hpp"

namespace ggxapp {

using BenchJob = ggxcl::benchmark::Job;
inline constexpr BenchJob all_bench_jobs[] = {BenchJob::write,      BenchJob::write_o,    BenchJob::furnace,
                                              BenchJob::world,      BenchJob::per_sample, BenchJob::store};
std::string job_name(BenchJob job);

// Nanoseconds per sample: median, fastest and slowest of the timed runs.
struct Timing {
    double median = 0, low = 0, high = 0;
};
Timing summarize(std::vector<double> ns_per_sample);
// "median (low–high)", each with `digits` digits after the point.
std::string timing_text(const Timing& t, int digits);

// Nanoseconds per sample of one call of `call`, which draws `count` samples, by wall clock.
double wall_ns_per_sample(const std::function<void()>& call, std::uint64_t count);

// The world job's inputs: unit normals over the sphere (away from the pole -z, where caps-iso is
// singular) and unit views at 0..87 degrees from them; the per-sample job's: the same views turned
// above z = 0 and alpha pairs in 0.05 .. 1.  `count` of each, at most 2^22; made once per run.
ggxcl::benchmark::JobInputs random_job_inputs(std::uint64_t count);

inline const std::string profiled_clock = "event-profiled";

// One device of the run: its API choice, back end and jobs, and how its rows were timed.
struct BenchDevice {
    ApiChoice choice;
    std::unique_ptr<ggxcl::Backend> backend;
    std::unique_ptr<ggxcl::benchmark::DeviceJobs> jobs;
    std::string clock;  // time_interleaved says: profiled_clock, or "wall-clock (launch to finish: why)"
    std::string label() const { return backend->device_label(); }
};

// `choice`'s device with its jobs of `count` samples on `inputs`.
BenchDevice open_bench_device(const ApiChoice& choice, std::uint32_t count, const ggxcl::benchmark::JobInputs& inputs);

struct BenchTask {
    BenchJob job;
    ggxcl::SampleParams params;  // guards = false: the write job without the fallbacks
    BenchDevice* device = nullptr;
};

// Warms every task up, then runs `repeats` rounds of all tasks in turn, so that the machine's
// drift spreads over all of them alike and their ratios stay meaningful on a noisy machine.
std::vector<Timing> time_interleaved(const std::vector<BenchTask>& tasks, int repeats);

} // namespace ggxapp
