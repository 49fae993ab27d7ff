// benchmark.cpp - the unguarded launches of ggxcl/benchmark.hpp.
#include "ggxcl/benchmark.hpp"

namespace ggxcl::benchmark {

cl::Event enqueue_unguarded(Sampler& sampler, cl::CommandQueue& queue, const SampleParams& params,
                            const SampleRange& range, const DeviceOutputs& outputs)
{
    return sampler.enqueue_variant(queue, params, range, outputs, 0, {}, nullptr, false);
}

cl::Event enqueue_furnace_unguarded(Sampler& sampler, cl::CommandQueue& queue, const SampleParams& params,
                                    const SampleRange& range, const cl::Buffer& sums)
{
    return sampler.enqueue_furnace_variant(queue, params, range, sums, {}, nullptr, false);
}

} // namespace ggxcl::benchmark
