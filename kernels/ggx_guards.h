// ggx_guards.h - what every sampler returns outside its domain, so that no
// input makes NaN or Inf: the fallback sample m = o = n, pdf_m = pdf_o =
// weight = 0, which a renderer reads as "no sample" (docs/STABILITY.md
// lists where each method falls back).  A sample falls back when a
// roughness is not a finite number > 0, or when the one quantity its method
// divides by the visible area with is not below 1e20: 1/(iz + t(i)) (the
// view exactly opposite the normal sees nothing, and one within rounding of
// it too little for a density in float range) and, for caps-iso, 1/(1 + nz)
// (its half-turn about n + z is undefined at n = -z, and a view within
// rounding of -n about a tilted n gives a half vector of length 0: caps-iso
// adds m.z to its key).
// Guards test a single value each: checking every output lets LLVM's SLP
// vectorizer pack the checks into short vectors, which blocks PoCL's
// work-item vectorizer (measured: 1.4 -> 13 ns per sample).  Finiteness is
// read from the exponent bits, which -cl-fast-relaxed-math cannot assume
// away.  Build option GGX_GUARDS=0 removes the guards (to measure their cost).
#ifndef GGX_GUARDS_H
#define GGX_GUARDS_H

#include "ggx_common.h"

#ifndef GGX_GUARDS
#define GGX_GUARDS 1
#endif

GGX_INLINE int ggx_is_finite(ggx_real x)
{
    return ggx_to_int((ggx_as_uint(x) & 0x7f800000u) != 0x7f800000u);
}

// A roughness usable by the samplers: finite and > 0 (float compares, false
// for NaN; bit tests here would be paired by the SLP vectorizer with the one
// on m, see below).
GGX_INLINE int ggx_roughness_ok(ggx_real ax, ggx_real ay)
{
    return ggx_to_int(ax > GGX_R(0.0f) && ay > GGX_R(0.0f) && ax <= GGX_FLT_MAX && ay <= GGX_FLT_MAX);
}

// The fallback sample about the unit normal n: m = o = n, pdfs and weight 0.
GGX_INLINE ggx_sample ggx_fallback_sample(ggx_vec3 n)
{
    ggx_sample result;
    result.m = n;
    result.o = n;
    result.pdf_m = GGX_R(0.0f);
    result.pdf_o = GGX_R(0.0f);
    result.weight = GGX_R(0.0f);
    return result;
}

// s when `ok`, else the fallback about the unit normal n: per-component
// selects, since a select of structs does not vectorize.
GGX_INLINE ggx_sample ggx_keep_or_fallback(ggx_sample s, int ok, ggx_vec3 n)
{
    bool keep = ok != 0;
    ggx_sample result;
    result.m = ggx_vec3_make(keep ? s.m.x : n.x, keep ? s.m.y : n.y, keep ? s.m.z : n.z);
    result.o = ggx_vec3_make(keep ? s.o.x : n.x, keep ? s.o.y : n.y, keep ? s.o.z : n.z);
    result.pdf_m = keep ? s.pdf_m : GGX_R(0.0f);
    result.pdf_o = keep ? s.pdf_o : GGX_R(0.0f);
    result.weight = keep ? s.weight : GGX_R(0.0f);
    return result;
}

// s when the roughness is usable and `key` < 1e20, else the fallback about
// the unit normal n.
GGX_INLINE ggx_sample ggx_guard_about(ggx_sample s, ggx_real key, ggx_vec3 n, ggx_real ax, ggx_real ay)
{
#if GGX_GUARDS
    // key < 1e20 (false for NaN and Inf): a visible area below 1e-20 makes densities beyond float
    // range.  For a uniform view and roughness `ok` is uniform: the guard costs a select per field.
    // (The bit test keeps it under -cl-fast-relaxed-math, which may fold compares with NaN and Inf.)
    int ok = ggx_roughness_ok(ax, ay) & ggx_to_int(key < GGX_R(1e20f)) & ggx_is_finite(key);
    return ggx_keep_or_fallback(s, ok, n);
#else
    return s;
#endif
}

// The same in tangent space, n = (0, 0, 1).
GGX_INLINE ggx_sample ggx_guard(ggx_sample s, ggx_real key, ggx_real ax, ggx_real ay)
{
    return ggx_guard_about(s, key, ggx_vec3_make(GGX_R(0.0f), GGX_R(0.0f), GGX_R(1.0f)), ax, ay);
}

// A pdf of a direction: 0 for an unusable roughness or where it is not finite.
GGX_INLINE ggx_real ggx_guard_pdf(ggx_real pdf, ggx_real ax, ggx_real ay)
{
#if GGX_GUARDS
    return (ggx_roughness_ok(ax, ay) & ggx_is_finite(pdf)) != 0 ? pdf : GGX_R(0.0f);
#else
    return pdf;
#endif
}

#endif
