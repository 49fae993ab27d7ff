// ggx_bulk_params.h - what the bulk kernels share (OpenCL C only): the
// sample of an index in tangent or world space (GGX_WORLD_SPACE=0|1), the
// view, roughness and normal of sample j, uniform or per sample
// (build options GGX_PER_SAMPLE_{VIEW,ALPHA,NORMAL}=0|1), and its two
// uniforms: from the sequence GGX_SEQUENCE (a GGX_SEQUENCE_* id of
// ggx_contract.h, Philox by default) or, with GGX_PER_SAMPLE_UNIFORMS=1,
// the caller's.  GGX_ISOTROPIC=1 promises alpha_x == alpha_y: one roughness
// is read and used for both.  GGX_DIELECTRIC=1 samples a rough dielectric
// of relative index `eta` (ggx_dielectric.h) with a third uniform for the
// lobe, in radiance transport, or importance with GGX_IMPORTANCE=1;
// GGX_DIELECTRIC=0 reflects with Fresnel 1 and ignores eta.
#ifndef GGX_BULK_PARAMS_H
#define GGX_BULK_PARAMS_H

// The bulk kernels are built for one method (see GGX_ONLY_METHOD in ggx_samplers.h).
#if defined(GGX_METHOD) && !defined(GGX_ONLY_METHOD)
#define GGX_ONLY_METHOD GGX_METHOD
#endif
#include "ggx_kernel_io.h"
#include "ggx_sobol.h"
#include "ggx_world.h"

#ifndef GGX_PER_SAMPLE_VIEW
#define GGX_PER_SAMPLE_VIEW 0
#endif
#ifndef GGX_PER_SAMPLE_ALPHA
#define GGX_PER_SAMPLE_ALPHA 0
#endif
#ifndef GGX_PER_SAMPLE_NORMAL
#define GGX_PER_SAMPLE_NORMAL 0
#endif
#ifndef GGX_PER_SAMPLE_UNIFORMS
#define GGX_PER_SAMPLE_UNIFORMS 0
#endif
#ifndef GGX_SEQUENCE
#define GGX_SEQUENCE GGX_SEQUENCE_PHILOX
#endif
#if GGX_SEQUENCE != GGX_SEQUENCE_PHILOX && GGX_SEQUENCE != GGX_SEQUENCE_SOBOL
#error "GGX_SEQUENCE: not a sequence id (GGX_SEQUENCE_* of ggx_contract.h)"
#endif
#ifndef GGX_ISOTROPIC
#define GGX_ISOTROPIC 0
#endif
#ifndef GGX_WORLD_SPACE
#define GGX_WORLD_SPACE 0
#endif
#ifndef GGX_DIELECTRIC
#define GGX_DIELECTRIC 0
#endif
#ifndef GGX_IMPORTANCE
#define GGX_IMPORTANCE 0
#endif
#define GGX_RADIANCE (!GGX_IMPORTANCE)
// GGX_NORMAL_IS_Z=1 (default 0, see ggx_sample_caps_iso.h): the uniform
// normal is exactly (0, 0, 1).

// The view, roughness and normal of sample j, per sample or uniform, the
// relative index, and the caller's uniforms (u1, u2, and u3 with
// GGX_DIELECTRIC) with GGX_PER_SAMPLE_UNIFORMS=1.
typedef struct {
    ggx_vec3 view, normal;
    float ax, ay, eta;
    float u1, u2, u3;
} ggx_params;

// The kernel arguments that carry them (GGX_PARAM_ARG_COUNT, at the positions
// of ggx_contract.h): uniform values, per-sample buffers, then the offset in
// floats where each buffer's planes begin.  The kernels pass the buffers on
// from their offsets (GGX_PARAM_VALUES_AT) to what takes GGX_PARAM_ARGS.
#define GGX_PARAM_ARGS                                                                      \
    float view_x, float view_y, float view_z, float alpha_x, float alpha_y, float normal_x, \
        float normal_y, float normal_z, float eta, __global const float *GGX_RESTRICT view_in,  \
        __global const float *GGX_RESTRICT alpha_in, __global const float *GGX_RESTRICT normal_in, \
        __global const float *GGX_RESTRICT uniforms_in
#define GGX_PARAM_VALUES                                                                    \
    view_x, view_y, view_z, alpha_x, alpha_y, normal_x, normal_y, normal_z, eta, view_in, alpha_in, normal_in, \
        uniforms_in
#define GGX_PARAM_KERNEL_ARGS \
    GGX_PARAM_ARGS, ulong view_at, ulong alpha_at, ulong normal_at, ulong uniforms_at
#define GGX_PARAM_VALUES_AT                                                                              \
    view_x, view_y, view_z, alpha_x, alpha_y, normal_x, normal_y, normal_z, eta, view_in + view_at,      \
        alpha_in + alpha_at, normal_in + normal_at, uniforms_in + uniforms_at

GGX_INLINE ggx_params ggx_load_params(uint j, uint stride, GGX_PARAM_ARGS)
{
    ggx_params p;
#if GGX_PER_SAMPLE_VIEW
    p.view = ggx_load3(view_in, j, stride);
#else
    p.view = ggx_vec3_make(view_x, view_y, view_z);
#endif
#if GGX_PER_SAMPLE_ALPHA
    p.ax = alpha_in[j];
#if GGX_ISOTROPIC
    p.ay = p.ax;
#else
    p.ay = alpha_in[j + stride];
#endif
#else
    p.ax = alpha_x;
    p.ay = GGX_ISOTROPIC ? alpha_x : alpha_y;
#endif
#if GGX_PER_SAMPLE_NORMAL
    p.normal = ggx_load3(normal_in, j, stride);
#elif GGX_NORMAL_IS_Z
    p.normal = ggx_vec3_make(0.0f, 0.0f, 1.0f);
#else
    p.normal = ggx_vec3_make(normal_x, normal_y, normal_z);
#endif
#if GGX_PER_SAMPLE_UNIFORMS
    p.u1 = uniforms_in[j];
    p.u2 = uniforms_in[j + stride];
    p.u3 = GGX_DIELECTRIC ? uniforms_in[j + 2u * stride] : 0.0f;
#else
    p.u1 = 0.0f;
    p.u2 = 0.0f;
    p.u3 = 0.0f;
#endif
    p.eta = eta;
    return p;
}

// The uniforms of sample first + j of stream `seed` (j < 2^32): the
// caller's (read into p), or the sequence's; u3 (the lobe choice) with
// GGX_DIELECTRIC only, else 0.
GGX_INLINE void ggx_bulk_uniforms(ulong seed, ulong first, uint j, ggx_params p, float* u1, float* u2, float* u3)
{
#if GGX_PER_SAMPLE_UNIFORMS
    *u1 = p.u1;
    *u2 = p.u2;
    *u3 = p.u3;
#elif GGX_SEQUENCE == GGX_SEQUENCE_SOBOL
    ggx_uniform_pair u = ggx_sobol_launch_pair(seed, first, j);
    *u1 = u.u1;
    *u2 = u.u2;
    *u3 = GGX_DIELECTRIC ? ggx_sobol_launch_lobe_uniform(seed, first, j) : 0.0f;
#else
    ggx_uniform_pair u = ggx_philox_pair(seed, first + j);
    *u1 = u.u1;
    *u2 = u.u2;
    *u3 = GGX_DIELECTRIC ? ggx_lobe_uniform(seed, first + j) : 0.0f;
#endif
}

// Whether a caller's uniform lies in [0, 1) (-0 included): read from the
// bits, which -cl-fast-relaxed-math cannot assume away, so NaN fails too.
GGX_INLINE int ggx_unit_interval(float u)
{
    uint bits = as_uint(u);
    return bits < 0x3f800000u || bits == 0x80000000u;
}

// The normal the method works with: world space and caps-iso read it, the others use +z.
GGX_INLINE ggx_vec3 ggx_bulk_normal(ggx_params p)
{
    const int about_normal = GGX_WORLD_SPACE | ggx_method_world_space(GGX_METHOD);
    return about_normal ? p.normal : ggx_vec3_make(0.0f, 0.0f, 1.0f);
}

// The sample of uniforms (u1, u2, u3) for the method GGX_METHOD with
// parameters p: world-space view, normal and results with GGX_WORLD_SPACE=1,
// else tangent space; a dielectric's with GGX_DIELECTRIC=1.  The caller's
// uniforms outside [0, 1) give the fallback sample about the normal the
// method works with (ggx_guards.h; a dielectric's: on the view's side).
GGX_INLINE ggx_sample ggx_bulk_sample_of(ggx_params p, float u1, float u2, float u3)
{
#if GGX_DIELECTRIC && GGX_WORLD_SPACE
    ggx_sample s = ggx_sample_dielectric_world(GGX_METHOD, p.normal, p.view, p.ax, p.eta, GGX_RADIANCE, u1, u2, u3);
#elif GGX_DIELECTRIC
    ggx_sample s = ggx_sample_dielectric_method(GGX_METHOD, p.normal, p.view, p.ax, p.ay, p.eta, GGX_RADIANCE, u1, u2,
                                                u3);
#elif GGX_WORLD_SPACE
    ggx_sample s = ggx_sample_world(GGX_METHOD, p.normal, p.view, p.ax, u1, u2);
#else
    ggx_sample s = ggx_sample_method(GGX_METHOD, p.normal, p.view, p.ax, p.ay, u1, u2);
#endif
#if GGX_PER_SAMPLE_UNIFORMS
    ggx_vec3 n = ggx_bulk_normal(p);
#if GGX_DIELECTRIC
    n = ggx_scale(n, ggx_dot(p.view, n) < 0.0f ? -1.0f : 1.0f);
    const int u3_ok = ggx_unit_interval(u3);
#else
    const int u3_ok = 1;
#endif
    s = ggx_keep_or_fallback(s, ggx_unit_interval(u1) & ggx_unit_interval(u2) & u3_ok, n);
#endif
    return s;
}

// Sample first + j of stream `seed` with parameters p.
GGX_INLINE ggx_sample ggx_bulk_sample(ulong seed, ulong first, uint j, ggx_params p)
{
    float u1, u2, u3;
    ggx_bulk_uniforms(seed, first, j, p, &u1, &u2, &u3);
    return ggx_bulk_sample_of(p, u1, u2, u3);
}

// Whether a sample's o lies on the view's side of the surface (a dielectric's reflection).
GGX_INLINE int ggx_bulk_reflected(ggx_params p, ggx_sample s)
{
    const ggx_vec3 n = ggx_bulk_normal(p);
    return ggx_dot(p.view, n) * ggx_dot(s.o, n) > 0.0f;
}

// The BSDF value f |cos| of o (ggx_bsdf.h), Fresnel 1 or a dielectric's:
// about the normal for caps-iso and in world space.
GGX_INLINE float ggx_bulk_eval(ggx_params p, ggx_vec3 o)
{
    const int about_normal = GGX_WORLD_SPACE | ggx_method_world_space(GGX_METHOD);  // folded: build options
#if GGX_DIELECTRIC
    if (about_normal)
        return ggx_eval_dielectric_world(p.normal, p.view, o, p.ax, p.eta, GGX_RADIANCE);
    return ggx_eval_dielectric(p.view, o, p.ax, p.ay, p.eta, GGX_RADIANCE);
#else
    if (about_normal)
        return ggx_eval_reflection_world(p.normal, p.view, o, p.ax);
    return ggx_eval_reflection(p.view, o, p.ax, p.ay);
#endif
}

// The pdf of direction o for GGX_METHOD, in the space of ggx_bulk_sample.
GGX_INLINE float ggx_bulk_pdf(ggx_params p, ggx_vec3 o)
{
#if GGX_DIELECTRIC && GGX_WORLD_SPACE
    return ggx_pdf_dielectric_world(GGX_METHOD, p.normal, p.view, o, p.ax, p.eta);
#elif GGX_DIELECTRIC
    return ggx_pdf_dielectric_method(GGX_METHOD, p.normal, p.view, o, p.ax, p.ay, p.eta);
#elif GGX_WORLD_SPACE
    return ggx_pdf_world(GGX_METHOD, p.normal, p.view, o, p.ax);
#else
    return ggx_pdf_method(GGX_METHOD, p.normal, p.view, o, p.ax, p.ay);
#endif
}

#endif
