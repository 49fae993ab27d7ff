// benchmark.hpp - for measuring, nothing else: the Sampler's kernels built
// without the fallbacks of docs/STABILITY.md, so that outside a method's
// domain NaN and Inf become possible (`ggx bench` times its rows side by
// side with these), and the exact program a bench job builds, for offline
// compilers (`ggx bench` counts its operations).  ggxcl.hpp does not
// include this header.
#pragma once

#include <string>

#include "ggxcl/fields.hpp"
#include "ggxcl/sampler.hpp"

namespace ggxcl::benchmark {

// Sampler::enqueue without the guards.
cl::Event enqueue_unguarded(Sampler& sampler, cl::CommandQueue& queue, const SampleParams& params,
                            const SampleRange& range, const DeviceOutputs& outputs);

// Sampler::enqueue_furnace without the guards: as Sampler::furnace draws
// each launch first.
cl::Event enqueue_furnace_unguarded(Sampler& sampler, cl::CommandQueue& queue, const SampleParams& params,
                                    const SampleRange& range, const cl::Buffer& sums);

// The program a launch builds: the embedded source file (kernel_source(file)), the kernel function
// and the build options exactly as the Sampler passes them to the driver, the precision mode's and
// the device's own options (device_options) included.
struct ProgramText {
    std::string file, kernel, options;
};

// Sampler::enqueue of `params` writing `fields` to buffers (no per-sample inputs); guards = false:
// enqueue_unguarded.  Throws InvalidArgument as enqueue does for bad parameters or no field.
ProgramText enqueue_program(const Sampler& sampler, const SampleParams& params, FieldSet fields, bool guards = true);

// Sampler::enqueue_furnace of `params` (no per-sample inputs); guards = false: enqueue_furnace_unguarded.
ProgramText furnace_program(const Sampler& sampler, const SampleParams& params, bool guards = true);

} // namespace ggxcl::benchmark
