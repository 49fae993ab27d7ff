// ggx_histogram.cl - samples binned on the device: a 2-D histogram of o (or
// m) over (phi, cos theta) in bins of equal solid angle, so that any number
// of samples is counted without crossing to the host.  Two strategies, for
// the two kinds of device:
//   ggx_histogram           - each work-group counts its samples in local
//                             memory with atomics, then adds its non-zero bins
//                             to the global counts (GPUs: fast local atomics);
//   ggx_histogram_bins, then ggx_histogram_count
//                           - one work-item per sample writes its bin index
//                             (straight-line code that CPU compilers vectorize),
//                             then work-groups of one work-item count slices of
//                             those indices without atomics (CPUs, where local
//                             atomics serialize and stop the vectorizer).
//
// Build options: GGX_METHOD=<id>, GGX_BINS_Z, GGX_BINS_PHI, GGX_BIN_M=0|1
// (1 bins m, 0 bins o), plus those of ggx_bulk_params.h.
// The bin of a direction is ggx_histogram_bin.h's.  Two counters follow the
// bins: samples whose direction is not finite, and those ggx_counter_of
// keeps out of the bins (a dielectric's invalid samples, a user sampler's
// discarded ones).  A built-in conductor bins every o, its wasted
// reflections below the surface too.
#include "ggx_bulk_params.h"

#if !defined(GGX_METHOD) || !defined(GGX_BINS_Z) || !defined(GGX_BINS_PHI)
#error "build with -DGGX_METHOD, -DGGX_BINS_Z and -DGGX_BINS_PHI"
#endif
#include "ggx_histogram_bin.h"

#define GGX_COUNTERS (GGX_BINS + 2)

GGX_INLINE uint ggx_sample_bin(ulong seed, ulong first, uint j, uint count, GGX_PARAM_ARGS)
{
    ggx_params p = ggx_load_params(j, count, GGX_PARAM_VALUES);
    return ggx_counter_of(ggx_bulk_sample(seed, first, j, p));
}

// Work-group g counts samples [g * size * per_item, (g + 1) * size * per_item) of the launch.
__kernel void ggx_histogram(ulong seed, ulong first, uint count, uint per_item, GGX_PARAM_KERNEL_ARGS,
                            __global uint* counts)
{
    __local uint local_counts[GGX_COUNTERS];
    uint size = get_local_size(0), lid = get_local_id(0);
    for (uint b = lid; b < GGX_COUNTERS; b += size)
        local_counts[b] = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    uint base = get_group_id(0) * size * per_item;
    for (uint k = 0; k < per_item; ++k) {
        uint j = base + k * size + lid;
        if (j < count)
            atomic_inc(&local_counts[ggx_sample_bin(seed, first, j, count, GGX_PARAM_VALUES_AT)]);
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint b = lid; b < GGX_COUNTERS; b += size)
        if (local_counts[b] != 0u)
            atomic_add(&counts[b], local_counts[b]);
}

// The bin index of sample j of the launch, for j < count (whole work-groups
// and a tail launch, as the bulk kernels).
__kernel void ggx_histogram_bins(ulong seed, ulong first, uint count, uint per_item, GGX_PARAM_KERNEL_ARGS,
                                 __global uint* GGX_RESTRICT bins)
{
    uint j = get_global_id(0);
    bins[j] = ggx_sample_bin(seed, first, j, count, GGX_PARAM_VALUES_AT);
}

__kernel void ggx_histogram_bins_tail(ulong seed, ulong first, uint count, uint per_item, GGX_PARAM_KERNEL_ARGS,
                                      __global uint* GGX_RESTRICT bins)
{
    uint j = min((uint)get_global_id(0), count - 1u);  // the last sample again past the end: no branch
    bins[j] = ggx_sample_bin(seed, first, j, count, GGX_PARAM_VALUES_AT);
}

// Work-item g (alone in its work-group) counts bins[g * per_item, (g + 1) * per_item) of count.
__kernel void ggx_histogram_count(__global const uint* bins, uint count, uint per_item, __global uint* counts)
{
    __local uint local_counts[GGX_COUNTERS];
    for (uint b = 0; b < GGX_COUNTERS; ++b)
        local_counts[b] = 0u;
    uint begin = get_global_id(0) * per_item;
    uint end = min(count, begin + per_item);
    for (uint j = begin; j < end; ++j)
        ++local_counts[bins[j]];
    for (uint b = 0; b < GGX_COUNTERS; ++b)
        if (local_counts[b] != 0u)
            atomic_add(&counts[b], local_counts[b]);
}
