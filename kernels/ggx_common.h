// ggx_common.h - shared device-side helpers for every ggxcl device header:
// constants, a struct of three scalars (ggx_real: float unless the build
// asks for half, ggx_platform.h) and the few vector operations the samplers
// need (the language constructs are in ggx_platform.h).
//
// The math is written on scalar floats: `ggx_vec3` is a plain struct, not the
// OpenCL `float3` vector type, so after inlining it dissolves into scalars
// and PoCL can turn the work-items of a work-group into SIMD lanes (float3
// values and out-of-line calls in the hot path block LLVM's vectorizer).
#ifndef GGX_COMMON_H
#define GGX_COMMON_H

#include "ggx_platform.h"

#define GGX_PI GGX_R(3.14159265358979323846f)
#define GGX_TWO_PI GGX_R(6.28318530717958647692f)
#define GGX_INV_PI GGX_R(0.31830988618379067154f)

// In GLSL and HLSL ggx_vec3 is the language's vec3 / float3 (ggx_platform_shader.h).
#if !GGX_SHADER
typedef struct {
    ggx_real x, y, z;
} ggx_vec3;
#endif

// What every sampler returns: the microfacet normal m, the reflected
// direction o, their densities (per steradian) and the white-furnace
// estimator weight f(i,o) cos(o) / pdf(o) with Fresnel 1 (0 when wasted).
struct ggx_sample {
    ggx_vec3 m, o;
    ggx_real pdf_m, pdf_o, weight;
};
GGX_TYPEDEF_STRUCT(ggx_sample)

GGX_INLINE ggx_vec3 ggx_vec3_make(ggx_real x, ggx_real y, ggx_real z)
{
#if GGX_SHADER
    return ggx_vec3(x, y, z);
#else
    ggx_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
#endif
}

GGX_INLINE ggx_real ggx_dot(ggx_vec3 a, ggx_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

GGX_INLINE ggx_vec3 ggx_add(ggx_vec3 a, ggx_vec3 b)
{
    return ggx_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z);
}

GGX_INLINE ggx_vec3 ggx_scale(ggx_vec3 a, ggx_real s)
{
    return ggx_vec3_make(a.x * s, a.y * s, a.z * s);
}

GGX_INLINE ggx_vec3 ggx_normalize(ggx_vec3 a)
{
    return ggx_scale(a, ggx_rsqrt(ggx_dot(a, a)));
}

GGX_INLINE ggx_vec3 ggx_cross(ggx_vec3 a, ggx_vec3 b)
{
    return ggx_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

// Mirror reflection of i about the unit normal m: o = 2 (i.m) m - i.
GGX_INLINE ggx_vec3 ggx_reflect(ggx_vec3 i, ggx_vec3 m)
{
    ggx_real twice_dot = GGX_R(2.0f) * ggx_dot(i, m);
    return ggx_vec3_make(twice_dot * m.x - i.x, twice_dot * m.y - i.y, twice_dot * m.z - i.z);
}

// The stretch of Heitz 2018 sec. 2: (ax wx, ay wy, wz).  Its length is t(w).
GGX_INLINE ggx_vec3 ggx_stretch(ggx_vec3 w, ggx_real ax, ggx_real ay)
{
    return ggx_vec3_make(ax * w.x, ay * w.y, w.z);
}

// The form of a method's functions that the dispatchers of ggx_samplers.h
// call for every method alike: the normal n (read by world-space methods)
// and both roughnesses.  A tangent-space method's forms ignore n.
#define GGX_TANGENT_SPACE_DISPATCH(identifier)                                                                       \
    GGX_INLINE ggx_sample ggx_dispatch_sample_##identifier(ggx_vec3 n, ggx_vec3 i, ggx_real ax, ggx_real ay,        \
                                                           ggx_real u1, ggx_real u2)                                \
    {                                                                                                                \
        GGX_UNUSED(n);                                                                                               \
        return ggx_sample_##identifier(i, ax, ay, u1, u2);                                                           \
    }                                                                                                                \
    GGX_INLINE ggx_real ggx_dispatch_pdf_##identifier(ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay) \
    {                                                                                                                \
        GGX_UNUSED(n);                                                                                               \
        return ggx_pdf_##identifier(i, o, ax, ay);                                                                   \
    }

#endif
