// benchmark.hpp - for measuring, nothing else: the jobs `ggx bench` times,
// run on any back end's device (DeviceJobs), and the exact program an
// OpenCL job builds, for offline compilers (the bench counts its
// operations).  (The kernels without the fallbacks of docs/STABILITY.md,
// which the bench times beside the guarded ones, are SampleParams::guards =
// false.)  ggxcl.hpp does not include this header.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "ggxcl/backend.hpp"
#include "ggxcl/fields.hpp"
#include "ggxcl/params.hpp"

namespace ggxcl::benchmark {

// The program a launch builds: the embedded source file (kernel_source(file)), the kernel function
// and the build options exactly as the Sampler passes them to the driver, the precision mode's and
// the device's own options (device_options) included.
struct ProgramText {
    std::string file, kernel, options;
};

// The bench's jobs.  Each run draws its samples into memory the device writes and copies nothing
// to the host:
//   write      - m and pdf_m, the request's own view (with or without SampleParams::guards);
//   write_o    - o and pdf_o: what a dielectric (SampleParams::eta) draws, its lobe choice included;
//   furnace    - the fused white-furnace estimator as Backend::furnace runs it (unguarded, rerun
//                guarded only on a sum that is not finite);
//   world      - a world-space normal and view read per sample, o written (alpha_x, isotropic);
//   per_sample - a view and an alpha pair read per sample, m and pdf_m written;
//   store      - the write job's bytes stored by a kernel that computes nothing: its ceiling.
enum class Job { write, write_o, furnace, world, per_sample, store };

// One run: its time on the device from the API's profiling, and by wall clock from the call to
// the end of the work; device_ns < 0 where the API gave none.
struct RunTime {
    double device_ns = -1, wall_ns = 0;
};

// The world job's per-sample normals and views, and the per-sample job's views and alpha pairs,
// each as long as the samples those jobs draw.
struct JobInputs {
    PerSampleInputs world, per_sample;
};

class DeviceJobs {
public:
    virtual ~DeviceJobs() = default;
    // Whether this back end runs `job` (store: OpenCL's alone).
    virtual bool runs(Job job) const = 0;
    // Samples a run of `job` draws.
    virtual std::uint64_t samples(Job job) const = 0;
    // One run of `job` on `params` with `seed`, to the end of its work.  InvalidArgument for a job
    // this back end does not run, or as the Backend's calls.
    virtual RunTime run(Job job, const SampleParams& params, std::uint64_t seed) = 0;
    // The OpenCL C program a run of write, write_o or furnace builds (its guards as given; the
    // furnace's unguarded, as it runs), for clang; none for other jobs and on other APIs.  Throws
    // InvalidArgument for bad parameters.
    virtual std::optional<ProgramText> program(Job job, const SampleParams& params) const = 0;
};

// The jobs of `count` samples on `backend`'s device, which must outlive them.  OpenCL's run into
// device buffers made here, once, profiled by their events; other APIs' through the Backend's own
// calls (generate_chunk_views with a sink that copies nothing, furnace), by wall clock.
std::unique_ptr<DeviceJobs> device_jobs(Backend& backend, std::uint64_t count, JobInputs inputs);

} // namespace ggxcl::benchmark
