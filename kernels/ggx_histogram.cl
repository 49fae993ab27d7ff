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
// Bin of a unit d: z bin floor((dz + 1)/2 nz), phi bin k for phi in
// [2 pi k/nphi, 2 pi (k+1)/nphi), phi the angle of (dx, dy) in [0, 2 pi)
// (atan2's, with -0 as 0); index z_bin * nphi + phi_bin.  Two counters
// follow the bins: samples whose direction is not finite, and a dielectric's
// invalid samples (pdf_o = 0: no density anywhere, so no bin expects them).
// A conductor bins every o, its wasted reflections below the surface too.
#include "ggx_bulk_params.h"

#if !defined(GGX_METHOD) || !defined(GGX_BINS_Z) || !defined(GGX_BINS_PHI)
#error "build with -DGGX_METHOD, -DGGX_BINS_Z and -DGGX_BINS_PHI"
#endif
#ifndef GGX_BIN_M
#define GGX_BIN_M 0
#endif
#define GGX_BINS (GGX_BINS_Z * GGX_BINS_PHI)
#define GGX_COUNTERS (GGX_BINS + 2)

// The angle of (x, y) in [0, 2 pi) within 1e-5 rad: atan of min/max on
// [0, 1] by a polynomial, then the octant.  No call: it vectorizes.
GGX_INLINE float ggx_rough_angle(float x, float y)
{
    // |y| by a select, |x| by fabs: two identical fabs let LLVM's SLP
    // vectorizer pair them, which then stops PoCL's loop vectorizer.
    float ax = fabs(x), ay = y < 0.0f ? -y : y;
    float big = fmax(ax, ay), small = fmin(ax, ay);
    float a = big > 0.0f ? small / big : 0.0f;
    float s = a * a;
    float t = -1.172120e-2f;
    t = t * s + 5.265332e-2f;
    t = t * s - 1.1643287e-1f;
    t = t * s + 1.9354346e-1f;
    t = t * s - 3.3262347e-1f;
    t = t * s + 9.9997726e-1f;
    t *= a;
    t = ay > ax ? 0.5f * GGX_PI - t : t;
    t = x < 0.0f ? GGX_PI - t : t;
    return y < 0.0f ? GGX_TWO_PI - t : t;
}

// The phi bin: the edge nearest to the rough angle decides it.  Edge e is
// the direction (cos, sin) of 2 pi e / nphi from ggx_sincos_2pi (exact at the
// quarter turns, within an ulp elsewhere; computed, not loaded from a table,
// so that the code vectorizes); (x, y) on or counterclockwise of it lies in
// bin e, clockwise of it in bin e - 1 (the sign of edge x d).  Exact while
// the rough angle's error stays under half a bin (the host allows at most
// 2^16 phi bins: half a bin is 4.8e-5 rad).  The pole (0, 0) gets angle 0:
// bin 0.
GGX_INLINE int ggx_phi_bin(float x, float y)
{
    int e = (int)rint(ggx_rough_angle(x, y) * (GGX_BINS_PHI / GGX_TWO_PI));  // 0 .. nphi
    float s, c;
    ggx_sincos_2pi((float)e / (float)GGX_BINS_PHI, &s, &c);
    int b = c * y - s * x < 0.0f ? e - 1 : e;
    return b < 0 ? b + GGX_BINS_PHI : (b >= GGX_BINS_PHI ? b - GGX_BINS_PHI : b);
}

// A direction that is not finite is binned as (1, 0, 0) first, then counted apart.
GGX_INLINE uint ggx_bin_of(ggx_vec3 d)
{
    int finite = isfinite(d.x) && isfinite(d.y) && isfinite(d.z);
    float x = finite ? d.x : 1.0f, y = finite ? d.y : 0.0f, z = finite ? d.z : 0.0f;
    int zb = clamp((int)floor(0.5f * (z + 1.0f) * GGX_BINS_Z), 0, GGX_BINS_Z - 1);
    int pb = ggx_phi_bin(x, y);
    return finite ? (uint)(zb * GGX_BINS_PHI + pb) : (uint)GGX_BINS;
}

GGX_INLINE uint ggx_sample_bin(ulong seed, ulong first, uint j, uint count, GGX_PARAM_ARGS)
{
    ggx_params p = ggx_load_params(j, count, GGX_PARAM_VALUES);
    ggx_sample s = ggx_bulk_sample(seed, first, j, p);
    const uint bin = ggx_bin_of(GGX_BIN_M ? s.m : s.o);
#if GGX_DIELECTRIC && !GGX_BIN_M
    return s.pdf_o > 0.0f ? bin : (uint)GGX_BINS + 1u;
#else
    return bin;
#endif
}

// Work-group g counts samples [g * size * per_item, (g + 1) * size * per_item) of the launch.
__kernel void ggx_histogram(ulong seed, ulong first, uint count, uint per_item, GGX_PARAM_ARGS,
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
            atomic_inc(&local_counts[ggx_sample_bin(seed, first, j, count, GGX_PARAM_VALUES)]);
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    for (uint b = lid; b < GGX_COUNTERS; b += size)
        if (local_counts[b] != 0u)
            atomic_add(&counts[b], local_counts[b]);
}

// The bin index of sample j of the launch, for j < count (whole work-groups
// and a tail launch, as the bulk kernels).
__kernel void ggx_histogram_bins(ulong seed, ulong first, uint count, uint per_item, GGX_PARAM_ARGS,
                                 __global uint* GGX_RESTRICT bins)
{
    uint j = get_global_id(0);
    bins[j] = ggx_sample_bin(seed, first, j, count, GGX_PARAM_VALUES);
}

__kernel void ggx_histogram_bins_tail(ulong seed, ulong first, uint count, uint per_item, GGX_PARAM_ARGS,
                                      __global uint* GGX_RESTRICT bins)
{
    uint j = min((uint)get_global_id(0), count - 1u);  // the last sample again past the end: no branch
    bins[j] = ggx_sample_bin(seed, first, j, count, GGX_PARAM_VALUES);
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
