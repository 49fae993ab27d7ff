// bench_speed.hpp - the device timings of `ggx bench`: one job of one
// program variant, event-profiled (wall clock where the driver's timestamps
// cannot be right), the median of repeated runs after a warm-up run (which
// builds and JIT-compiles the variant).
//   write   - tangent-space view, m and pdf_m written to device buffers;
//   write-o - the same with o and pdf_o written: what a dielectric (SampleParams::eta)
//             draws, whose lobe choice m and pdf_m alone would leave out;
//   furnace - the fused white-furnace estimator, nothing written but sums
//             (a dielectric's reflected weights summed apart too);
//   world   - world-space normal and view read per sample, o written in world
//             space (classic methods build a basis, caps-iso needs none);
//   per-sample - a view and an anisotropic alpha read per sample from buffers
//             (the renderer's case), m and pdf_m written;
//   store   - the ceiling of the write job: a kernel that stores the same
//             bytes (m and pdf_m planes) and computes nothing.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace ggxapp {

enum class BenchJob { write, write_o, furnace, world, per_sample, store };
inline constexpr BenchJob all_bench_jobs[] = {BenchJob::write,      BenchJob::write_o,    BenchJob::furnace,
                                              BenchJob::world,      BenchJob::per_sample, BenchJob::store};
std::string job_name(BenchJob job);

// Nanoseconds per sample: median, fastest and slowest of the timed runs.
struct Timing {
    double median = 0, low = 0, high = 0;
};
Timing summarize(std::vector<double> ns_per_sample);

// Nanoseconds per sample of one call of `call`, which draws `count` samples, by wall clock.
double wall_ns_per_sample(const std::function<void()>& call, std::uint64_t count);

// The world job's inputs: planar unit normals over the sphere (away from the
// pole -z, where caps-iso is singular) and unit views at 0..87 degrees from them.
void random_world_inputs(std::uint32_t count, std::vector<float>& normals, std::vector<float>& views);

struct BenchTask {
    BenchJob job;
    ggxcl::SampleParams params;  // guards = false: the write job without the fallbacks
};

class DeviceTimer {
public:
    // Buffers for `count` samples (the world job uses at most 2^22, with
    // random normals over the sphere and views within 87 degrees of them).
    DeviceTimer(ggxcl::Sampler& sampler, std::uint32_t count);
    // Warms every task up, then runs `repeats` rounds of all tasks in turn,
    // so that the machine's drift spreads over all of them alike and their
    // ratios stay meaningful on a noisy machine.
    std::vector<Timing> time_interleaved(const std::vector<BenchTask>& tasks, int repeats);
    std::uint32_t count_of(BenchJob job) const;
    // How the last time_interleaved() timed: by the events' profiling
    // timestamps, or, when any of them could not be right (zero, missing, or
    // far from the wall-clock time of the run), by wall clock around each
    // launch and its wait, for every row alike.
    bool wall_clock() const { return wall_clock_; }
    std::string clock_description() const;

private:
    cl::Event launch(const BenchTask& task, std::uint64_t seed);

    ggxcl::Sampler& sampler_;
    std::uint32_t count_, world_count_;
    ggxcl::DeviceOutputs write_out_, write_o_out_, world_out_;  // write_o_out_: write_out_'s buffers
    ggxcl::DeviceInputs per_sample_in_;
    cl::Kernel store_;
    ggxcl::DeviceInputs world_in_;
    cl::Buffer sums_;
    bool wall_clock_ = false;
    std::string plausible_note_;
};

} // namespace ggxapp
