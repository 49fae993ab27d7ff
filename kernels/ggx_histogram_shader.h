// ggx_histogram_shader.h - the histogram shader's body, one text for GLSL
// (ggx_histogram.comp) and HLSL (ggx_histogram.hlsl): what ggx_histogram.cl's
// ggx_histogram kernel does per work-item.  Each work-group counts its
// samples in shared memory with atomics, then adds its non-zero counters to
// the global ones.  Counters: the GGX_BINS bins of ggx_histogram_bin.h, then
// directions that are not finite, then the samples ggx_counter_of keeps out
// of the bins (a dielectric's invalid ones, a user sampler's discarded ones).
// Build switches: those of ggx_bulk_sample.h, GGX_BINS_Z, GGX_BINS_PHI,
// GGX_BIN_M=0|1 (1 bins m) and GGX_GROUP_SIZE.
// The including shader declares first `ggx_counts` (a uint storage buffer
// of GGX_COUNTERS) and
// `ggx_local_counts` (uint[GGX_COUNTERS] of shared memory), and the
// language's GGX_LOCAL_ADD(index, value), GGX_GLOBAL_ADD(index, value) and
// GGX_GROUP_BARRIER(); ggx_request.stride is the samples per invocation.
#ifndef GGX_HISTOGRAM_SHADER_H
#define GGX_HISTOGRAM_SHADER_H

#include "ggx_histogram_bin.h"
#include "ggx_request_shader.h"

// The counter of sample j of the launch.
ggx_uint ggx_shader_sample_bin(ggx_uint j)
{
    return ggx_counter_of(ggx_bulk_sample(ggx_request_seed(), ggx_request_first(), j, ggx_request_params()));
}

// Invocation `local` of work-group `group` (the invocation y * row_width + x
// of the 2-D dispatch, split by GGX_GROUP_SIZE) counts samples
// group * size * per_item + k * size + local (k < per_item) below count.
void ggx_shader_histogram(ggx_uint group, ggx_uint local)
{
    const ggx_uint size = ggx_to_uint(GGX_GROUP_SIZE), per_item = ggx_request.stride;
    for (ggx_uint b = local; b < ggx_to_uint(GGX_COUNTERS); b += size)
        ggx_local_counts[b] = 0u;
    GGX_GROUP_BARRIER();
    const ggx_uint base = group * size * per_item;
    for (ggx_uint k = 0u; k < per_item; ++k) {
        const ggx_uint j = base + k * size + local;
        if (j < ggx_request.count)
            GGX_LOCAL_ADD(ggx_shader_sample_bin(j), 1u);
    }
    GGX_GROUP_BARRIER();
    for (ggx_uint b = local; b < ggx_to_uint(GGX_COUNTERS); b += size)
        if (ggx_local_counts[b] != 0u)
            GGX_GLOBAL_ADD(b, ggx_local_counts[b]);
}

#endif
