// ggx_histogram_bin.h - the histogram's bin of a direction, for the
// histogram kernels (OpenCL C) and shaders (GLSL, HLSL), apart from them so
// that a program that bins directions builds nothing else (no kernel, no
// local memory).
// Build options: GGX_BINS_Z, GGX_BINS_PHI, GGX_BIN_M=0|1 (1 bins m, 0 bins o).
// Bin of a unit d: z bin floor((dz + 1)/2 nz), phi bin k for phi in
// [2 pi k/nphi, 2 pi (k+1)/nphi), phi the angle of (dx, dy) in [0, 2 pi)
// (atan2's, with -0 as 0); index z_bin * nphi + phi_bin.  A direction that
// is not finite gets index GGX_BINS, the first after the bins.
#ifndef GGX_HISTOGRAM_BIN_H
#define GGX_HISTOGRAM_BIN_H

#include "ggx_common.h"
#include "ggx_contract.h"
#include "ggx_guards.h"
#include "ggx_sincos.h"

#if !defined(GGX_BINS_Z) || !defined(GGX_BINS_PHI)
#error "build with -DGGX_BINS_Z and -DGGX_BINS_PHI"
#endif
#define GGX_BINS (GGX_BINS_Z * GGX_BINS_PHI)
#ifndef GGX_BIN_M
#define GGX_BIN_M 0
#endif

// The angle of (x, y) in [0, 2 pi) within 1e-5 rad: atan of min/max on
// [0, 1] by a polynomial, then the octant.  No call: it vectorizes.
GGX_INLINE float ggx_rough_angle(float x, float y)
{
    // |y| by a select, |x| by fabs: two identical fabs let LLVM's SLP
    // vectorizer pair them, which then stops PoCL's loop vectorizer.
    float ax = ggx_fabs(x), ay = y < 0.0f ? -y : y;
    float larger = ggx_fmax(ax, ay), smaller = ggx_fmin(ax, ay);
    float a = larger > 0.0f ? smaller / larger : 0.0f;
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
    int e = ggx_to_int(ggx_rint(ggx_rough_angle(x, y) * (ggx_to_float(GGX_BINS_PHI) / GGX_TWO_PI)));  // 0 .. nphi
    ggx_sin_cos edge = ggx_sincos_2pi(ggx_to_float(e) / ggx_to_float(GGX_BINS_PHI));
    int b = edge.cosine * y - edge.sine * x < 0.0f ? e - 1 : e;
    return b < 0 ? b + GGX_BINS_PHI : (b >= GGX_BINS_PHI ? b - GGX_BINS_PHI : b);
}

// A direction that is not finite (read from its bits, which relaxed math
// cannot assume away) is binned as (1, 0, 0) first, then counted apart.
GGX_INLINE ggx_uint ggx_bin_of(ggx_vec3 d)
{
    const bool finite = (ggx_is_finite(d.x) & ggx_is_finite(d.y) & ggx_is_finite(d.z)) != 0;
    float x = finite ? d.x : 1.0f, y = finite ? d.y : 0.0f, z = finite ? d.z : 0.0f;
    int zb = clamp(ggx_to_int(floor(0.5f * (z + 1.0f) * ggx_to_float(GGX_BINS_Z))), 0, GGX_BINS_Z - 1);
    int pb = ggx_phi_bin(x, y);
    return finite ? ggx_to_uint(zb * GGX_BINS_PHI + pb) : ggx_to_uint(GGX_BINS);
}

// The counter of a sample: the bin of o (of m with GGX_BIN_M), or GGX_BINS + 1
// for a sample without a place in the bins: a dielectric's invalid one (pdf_o
// = 0, no density anywhere; o binned only), a user sampler's discarded one (o
// below the horizon with weight 0, whatever its pdf: an engine's rejected
// sample, docs/USER-SAMPLERS.md), o or m binned.
GGX_INLINE ggx_uint ggx_counter_of(ggx_sample s)
{
    const ggx_uint bin = ggx_bin_of(GGX_BIN_M != 0 ? s.m : s.o);
#if GGX_DIELECTRIC && !GGX_BIN_M
    return s.pdf_o > 0.0f ? bin : ggx_to_uint(GGX_BINS + 1);
#elif defined(GGX_METHOD) && GGX_METHOD == GGX_METHOD_USER
    return (s.o.z <= 0.0f && s.weight == 0.0f) ? ggx_to_uint(GGX_BINS + 1) : bin;
#else
    return bin;
#endif
}

#endif // GGX_HISTOGRAM_BIN_H
