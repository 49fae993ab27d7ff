// ggx_histogram.cl - samples binned on the device: a 2-D histogram of o (or
// m) over (phi, cos theta) in bins of equal solid angle, so that any number
// of samples is counted without crossing to the host.  Each work-group
// counts its samples in local memory with atomics, then adds its non-zero
// bins to the global counts.
//
// Build options: GGX_METHOD=<id>, GGX_BINS_Z, GGX_BINS_PHI, GGX_BIN_M=0|1
// (1 bins m, 0 bins o), plus those of ggx_bulk_params.h.
// Bin of a unit d: z bin floor((dz + 1)/2 nz), phi bin floor(phi/(2 pi) nphi)
// with phi = atan2(dy, dx) in [0, 2 pi); index z_bin * nphi + phi_bin.
// The extra last counter holds samples whose direction is not finite.
#include "ggx_bulk_params.h"

#if !defined(GGX_METHOD) || !defined(GGX_BINS_Z) || !defined(GGX_BINS_PHI)
#error "build with -DGGX_METHOD, -DGGX_BINS_Z and -DGGX_BINS_PHI"
#endif
#ifndef GGX_BIN_M
#define GGX_BIN_M 0
#endif
#define GGX_BINS (GGX_BINS_Z * GGX_BINS_PHI)

GGX_INLINE uint ggx_bin_of(ggx_vec3 d)
{
    int finite = isfinite(d.x) && isfinite(d.y) && isfinite(d.z);
    float phi = atan2(d.y, d.x);
    phi = phi < 0.0f ? phi + GGX_TWO_PI : phi;
    int zb = clamp((int)floor(0.5f * (d.z + 1.0f) * GGX_BINS_Z), 0, GGX_BINS_Z - 1);
    int pb = clamp((int)floor(phi * (GGX_BINS_PHI / GGX_TWO_PI)), 0, GGX_BINS_PHI - 1);
    return finite ? (uint)(zb * GGX_BINS_PHI + pb) : (uint)GGX_BINS;
}

// Work-group g counts samples [g * size * per_item, (g + 1) * size * per_item) of the launch.
__kernel void ggx_histogram(ulong seed, ulong first, uint count, uint per_item, GGX_PARAM_ARGS,
                            __global uint* counts)
{
    __local uint local_counts[GGX_BINS + 1];
    uint size = get_local_size(0), lid = get_local_id(0);
    for (uint b = lid; b <= GGX_BINS; b += size)
        local_counts[b] = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    uint base = get_group_id(0) * size * per_item;
    for (uint k = 0; k < per_item; ++k) {
        uint j = base + k * size + lid;
        if (j < count) {
            ggx_params p = ggx_load_params(j, count, GGX_PARAM_VALUES);
            ggx_sample s = ggx_bulk_sample(seed, first + j, p);
            atomic_inc(&local_counts[ggx_bin_of(GGX_BIN_M ? s.m : s.o)]);
        }
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint b = lid; b <= GGX_BINS; b += size)
        if (local_counts[b] != 0u)
            atomic_add(&counts[b], local_counts[b]);
}
