// benchmark.hpp - for measuring, nothing else: the exact program a bench
// job builds, for offline compilers (`ggx bench` counts its operations).
// (The kernels without the fallbacks of docs/STABILITY.md, which the bench
// times beside the guarded ones, are SampleParams::guards = false.)
// ggxcl.hpp does not include this header.
#pragma once

#include <string>

#include "ggxcl/fields.hpp"
#include "ggxcl/sampler.hpp"

namespace ggxcl::benchmark {

// The program a launch builds: the embedded source file (kernel_source(file)), the kernel function
// and the build options exactly as the Sampler passes them to the driver, the precision mode's and
// the device's own options (device_options) included.
struct ProgramText {
    std::string file, kernel, options;
};

// Sampler::enqueue of `params` (its guards included) writing `fields` to buffers (no per-sample
// inputs).  Throws InvalidArgument as enqueue does for bad parameters or no field.
ProgramText enqueue_program(const Sampler& sampler, const SampleParams& params, FieldSet fields);

// Sampler::enqueue_furnace of `params` (no per-sample inputs).
ProgramText furnace_program(const Sampler& sampler, const SampleParams& params);

} // namespace ggxcl::benchmark
