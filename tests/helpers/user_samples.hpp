// user_samples.hpp - samples drawn two ways for bit comparisons: by a user
// kernel calling the device headers (ggx_uniforms + ggx_sample_method), and
// by Sampler::enqueue into the caller's buffers on the caller's queue.  Both
// return 9 planes of `count` floats: m (x, y, z), o (x, y, z), pdf_m, pdf_o,
// weight.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace ggxtest {

using SamplePlanes = std::vector<float>;

// The user kernel `user_samples`, with `#include "ggx_samplers.h"` at its
// top or (to prepend the embedded text instead) without.
std::string user_samples_source(bool include_header);

// Runs `user_samples` of `program` (built on sampler's context) for the
// normalized params and the range.
SamplePlanes run_user_samples(ggxcl::Sampler& sampler, const cl::Program& program, const ggxcl::SampleParams& params,
                              const ggxcl::SampleRange& range);

// Every field of the range enqueued on `queue`, not yet read back.
struct PendingSamples {
    cl::CommandQueue queue;
    ggxcl::DeviceOutputs outputs;
    std::uint64_t count = 0;
};
PendingSamples start_samples(ggxcl::Sampler& sampler, cl::CommandQueue queue, const ggxcl::SampleParams& params,
                             const ggxcl::SampleRange& range);
SamplePlanes finish_samples(PendingSamples& pending);

// start_samples then finish_samples.
SamplePlanes enqueue_samples(ggxcl::Sampler& sampler, cl::CommandQueue& queue, const ggxcl::SampleParams& params,
                             const ggxcl::SampleRange& range);

// The planes of two consecutive ranges as the planes of their union.
SamplePlanes join_planes(const SamplePlanes& first, const SamplePlanes& second);

} // namespace ggxtest
