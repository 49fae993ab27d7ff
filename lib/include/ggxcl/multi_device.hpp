// multi_device.hpp - one job split across several devices: chunk k of the
// range goes to sampler k mod S, the samplers run in parallel threads, and
// the sink receives the chunks in order.  Sample k depends only on
// (seed, k), so the result has the same bits as one device of the same type
// would give.  At most two chunks per sampler wait in memory.  It may be
// called from several threads at once; the sink runs on the calling thread.
#pragma once

#include <vector>

#include "ggxcl/sampler.hpp"

namespace ggxcl {

void generate_split(const std::vector<Sampler*>& samplers, const SampleParams& params, const SampleRange& range,
                    FieldSet fields, const Sampler::ChunkSink& sink, std::uint64_t chunk_size = 1u << 20);

} // namespace ggxcl
