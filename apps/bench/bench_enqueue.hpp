// bench_enqueue.hpp - the host cost of a small batch: one Sampler::enqueue
// of 4096 caps samples (m and pdf_m into the caller's buffers) with every
// cache warm, timed from call to return, the median of 1000 calls; the
// queue is drained between calls, outside the timing.  Also the first
// enqueue on a second Sampler of the same context (its programs shared),
// and an enqueue and its finish with the buffers at offset 0 and at an odd
// offset, alternated call by call (what an offset costs: nothing, the
// kernels take it).  On the run's OpenCL device: the caller's buffers are
// OpenCL's (a run without OpenCL has no such rows).
#pragma once

#include <ggxcl/ggxcl.hpp>

#include "api_options.hpp"
#include "bench_report.hpp"

namespace ggxapp {

EnqueueTiming measure_enqueue(const std::vector<ApiChoice>& apis, const ggxcl::SampleParams& params);

} // namespace ggxapp
