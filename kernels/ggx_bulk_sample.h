// ggx_bulk_sample.h - what every bulk kernel and bulk shader computes per
// sample, in OpenCL C, GLSL and HLSL alike: the sample of an index in
// tangent or world space (GGX_WORLD_SPACE=0|1) from the view, roughness and
// normal of sample j (ggx_params: uniform or per sample, as the kernel or
// shader loads them) and its uniforms: from the sequence GGX_SEQUENCE (a
// GGX_SEQUENCE_* id of ggx_contract.h, Philox by default) or, with
// GGX_PER_SAMPLE_UNIFORMS=1, the caller's.  GGX_ISOTROPIC=1 promises
// alpha_x == alpha_y: one roughness is read and used for both.
// GGX_DIELECTRIC=1 samples a rough dielectric of relative index `eta`
// (ggx_dielectric.h) with a third uniform for the lobe, in radiance
// transport, or importance with GGX_IMPORTANCE=1; GGX_DIELECTRIC=0 reflects
// with Fresnel 1 and ignores eta.  The loads from buffers are each
// language's own (ggx_bulk_params.h for OpenCL C, ggx_bulk_shader.h).
#ifndef GGX_BULK_SAMPLE_H
#define GGX_BULK_SAMPLE_H

// The bulk kernels are built for one method (see GGX_ONLY_METHOD in ggx_samplers.h).
#if defined(GGX_METHOD) && !defined(GGX_ONLY_METHOD)
#define GGX_ONLY_METHOD GGX_METHOD
#endif
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
#if GGX_IMPORTANCE
#define GGX_RADIANCE 0
#else
#define GGX_RADIANCE 1
#endif
// GGX_NORMAL_IS_Z=1 (default 0, see ggx_sample_caps_iso.h): the uniform
// normal is exactly (0, 0, 1).

// The fields a bulk program computes and stores: bit 1 << GGX_FIELD_* of
// ggx_contract.h; the pdf programs write the BSDF value instead with GGX_EVAL=1.
#ifndef GGX_WRITE_MASK
#define GGX_WRITE_MASK 0
#endif
#if GGX_WRITE_MASK < 0 || GGX_WRITE_MASK >= (1 << GGX_FIELD_COUNT)
#error "GGX_WRITE_MASK: bits 1 << GGX_FIELD_* of ggx_contract.h only"
#endif
#ifndef GGX_EVAL
#define GGX_EVAL 0
#endif
#define GGX_WRITE_M ((GGX_WRITE_MASK >> GGX_FIELD_M) & 1)
#define GGX_WRITE_O ((GGX_WRITE_MASK >> GGX_FIELD_O) & 1)
#define GGX_WRITE_PDF_M ((GGX_WRITE_MASK >> GGX_FIELD_PDF_M) & 1)
#define GGX_WRITE_PDF_O ((GGX_WRITE_MASK >> GGX_FIELD_PDF_O) & 1)
#define GGX_WRITE_WEIGHT ((GGX_WRITE_MASK >> GGX_FIELD_WEIGHT) & 1)
#define GGX_WRITE_U ((GGX_WRITE_MASK >> GGX_FIELD_U) & 1)

// The view, roughness and normal of sample j, per sample or uniform, the
// relative index, and the caller's uniforms (u1, u2, and u3 with
// GGX_DIELECTRIC) with GGX_PER_SAMPLE_UNIFORMS=1.
struct ggx_params {
    ggx_vec3 view, normal;
    float ax, ay, eta;
    float u1, u2, u3;
};
GGX_TYPEDEF_STRUCT(ggx_params)

// p with the uniforms of sample first + j of stream `seed` (j < 2^32): the
// caller's (already in p), or the sequence's; u3 (the lobe choice) with
// GGX_DIELECTRIC only, else 0.
GGX_INLINE ggx_params ggx_bulk_uniforms(ggx_ulong seed, ggx_ulong first, ggx_uint j, ggx_params p)
{
#if GGX_PER_SAMPLE_UNIFORMS
    GGX_UNUSED(seed);
    GGX_UNUSED(first);
    GGX_UNUSED(j);
#elif GGX_SEQUENCE == GGX_SEQUENCE_SOBOL
    ggx_uniform_pair u = ggx_sobol_launch_pair(seed, first, j);
    p.u1 = u.u1;
    p.u2 = u.u2;
    p.u3 = GGX_DIELECTRIC != 0 ? ggx_sobol_launch_lobe_uniform(seed, first, j) : 0.0f;
#else
    ggx_uniform_pair u = ggx_philox_pair(seed, first + ggx_to_ulong(j));
    p.u1 = u.u1;
    p.u2 = u.u2;
    p.u3 = GGX_DIELECTRIC != 0 ? ggx_lobe_uniform(seed, first + ggx_to_ulong(j)) : 0.0f;
#endif
    return p;
}

// Whether a caller's uniform lies in [0, 1) (-0 included): read from the
// bits, which -cl-fast-relaxed-math cannot assume away, so NaN fails too.
GGX_INLINE int ggx_unit_interval(float u)
{
    ggx_uint bits = ggx_as_uint(u);
    return ggx_to_int(bits < 0x3f800000u || bits == 0x80000000u);
}

// The normal the method works with: world space and caps-iso read it, the others use +z.
GGX_INLINE ggx_vec3 ggx_bulk_normal(ggx_params p)
{
    const bool about_normal = (GGX_WORLD_SPACE | ggx_method_world_space(GGX_METHOD)) != 0;
    return about_normal ? p.normal : ggx_vec3_make(0.0f, 0.0f, 1.0f);
}

// The sample of p's uniforms (u1, u2, u3) for the method GGX_METHOD with
// parameters p: world-space view, normal and results with GGX_WORLD_SPACE=1,
// else tangent space; a dielectric's with GGX_DIELECTRIC=1.  The caller's
// uniforms outside [0, 1) give the fallback sample about the normal the
// method works with (ggx_guards.h; a dielectric's: on the view's side).
GGX_INLINE ggx_sample ggx_bulk_sample_of(ggx_params p)
{
    const float u1 = p.u1, u2 = p.u2, u3 = p.u3;
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
    GGX_UNUSED(u3);
#endif
    s = ggx_keep_or_fallback(s, ggx_unit_interval(u1) & ggx_unit_interval(u2) & u3_ok, n);
#endif
    return s;
}

// Sample first + j of stream `seed` with parameters p.
GGX_INLINE ggx_sample ggx_bulk_sample(ggx_ulong seed, ggx_ulong first, ggx_uint j, ggx_params p)
{
    return ggx_bulk_sample_of(ggx_bulk_uniforms(seed, first, j, p));
}

// Whether a sample's o lies on the view's side of the surface (a dielectric's reflection).
GGX_INLINE bool ggx_bulk_reflected(ggx_params p, ggx_sample s)
{
    const ggx_vec3 n = ggx_bulk_normal(p);
    return ggx_dot(p.view, n) * ggx_dot(s.o, n) > 0.0f;
}

// The BSDF value f |cos| of o (ggx_bsdf.h), Fresnel 1 or a dielectric's:
// about the normal for caps-iso and in world space.
GGX_INLINE float ggx_bulk_eval(ggx_params p, ggx_vec3 o)
{
    const bool about_normal = (GGX_WORLD_SPACE | ggx_method_world_space(GGX_METHOD)) != 0;  // folded: build options
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
