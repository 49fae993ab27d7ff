// benchmark.hpp - for measuring what the guards cost, nothing else: the
// Sampler's kernels built without the fallbacks of docs/STABILITY.md, so
// that outside a method's domain NaN and Inf become possible.  `ggx bench`
// times its rows side by side with these; ggxcl.hpp does not include this
// header.
#pragma once

#include "ggxcl/sampler.hpp"

namespace ggxcl::benchmark {

// Sampler::enqueue without the guards.
cl::Event enqueue_unguarded(Sampler& sampler, cl::CommandQueue& queue, const SampleParams& params,
                            const SampleRange& range, const DeviceOutputs& outputs);

// Sampler::enqueue_furnace without the guards: as Sampler::furnace draws
// each launch first.
cl::Event enqueue_furnace_unguarded(Sampler& sampler, cl::CommandQueue& queue, const SampleParams& params,
                                    const SampleRange& range, const cl::Buffer& sums);

} // namespace ggxcl::benchmark
