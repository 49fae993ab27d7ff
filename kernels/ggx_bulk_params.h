// ggx_bulk_params.h - what the bulk kernels share: planar loads and stores,
// the sample of an index in tangent or world space (GGX_WORLD_SPACE=0|1),
// and the view, roughness and normal of sample j, uniform or per sample
// (build options GGX_PER_SAMPLE_{VIEW,ALPHA,NORMAL}=0|1).  GGX_ISOTROPIC=1
// promises alpha_x == alpha_y: one roughness is read and used for both.
#ifndef GGX_BULK_PARAMS_H
#define GGX_BULK_PARAMS_H

// The bulk kernels are built for one method (see GGX_ONLY_METHOD in ggx_samplers.h).
#if defined(GGX_METHOD) && !defined(GGX_ONLY_METHOD)
#define GGX_ONLY_METHOD GGX_METHOD
#endif
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
#ifndef GGX_ISOTROPIC
#define GGX_ISOTROPIC 0
#endif
#ifndef GGX_WORLD_SPACE
#define GGX_WORLD_SPACE 0
#endif
// GGX_NORMAL_IS_Z=1 (default 0, see ggx_sample_caps_iso.h): the uniform
// normal is exactly (0, 0, 1).

GGX_INLINE ggx_vec3 ggx_load3(__global const float* p, uint j, uint stride)
{
    return ggx_vec3_make(p[j], p[j + stride], p[j + 2u * stride]);
}

GGX_INLINE void ggx_store3(__global float* p, uint j, uint stride, ggx_vec3 v)
{
    p[j] = v.x;
    p[j + stride] = v.y;
    p[j + 2u * stride] = v.z;
}

// The view, roughness and normal of sample j: per sample or uniform.
typedef struct {
    ggx_vec3 view, normal;
    float ax, ay;
} ggx_params;

// The kernel arguments that carry them (GGX_PARAM_ARG_COUNT, at the positions
// of ggx_contract.h): uniform values, then per-sample buffers.
#define GGX_PARAM_ARGS                                                                      \
    float view_x, float view_y, float view_z, float alpha_x, float alpha_y, float normal_x, \
        float normal_y, float normal_z, __global const float *GGX_RESTRICT view_in,             \
        __global const float *GGX_RESTRICT alpha_in, __global const float *GGX_RESTRICT normal_in
#define GGX_PARAM_VALUES                                                                    \
    view_x, view_y, view_z, alpha_x, alpha_y, normal_x, normal_y, normal_z, view_in, alpha_in, normal_in

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
    return p;
}

// Sample `index` of stream `seed` for the method GGX_METHOD with parameters p:
// world-space view, normal and results with GGX_WORLD_SPACE=1, else tangent space.
GGX_INLINE ggx_sample ggx_bulk_sample(ulong seed, ulong index, ggx_params p)
{
    float u1, u2;
    ggx_uniforms(seed, index, &u1, &u2);
#if GGX_WORLD_SPACE
    return ggx_sample_world(GGX_METHOD, p.normal, p.view, p.ax, u1, u2);
#else
    return ggx_sample_method(GGX_METHOD, p.normal, p.view, p.ax, p.ay, u1, u2);
#endif
}

// The pdf of direction o for GGX_METHOD, in the space of ggx_bulk_sample.
GGX_INLINE float ggx_bulk_pdf(ggx_params p, ggx_vec3 o)
{
#if GGX_WORLD_SPACE
    return ggx_pdf_world(GGX_METHOD, p.normal, p.view, o, p.ax);
#else
    return ggx_pdf_method(GGX_METHOD, p.normal, p.view, o, p.ax, p.ay);
#endif
}

#endif
