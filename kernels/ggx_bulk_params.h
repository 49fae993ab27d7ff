// ggx_bulk_params.h - the bulk kernels' parameters in OpenCL C: the
// kernel arguments that carry the view, roughness, normal and relative
// index (uniform values, per-sample buffers and their offsets) and the load
// of sample j's from them (build options GGX_PER_SAMPLE_{VIEW,ALPHA,NORMAL,
// UNIFORMS}=0|1); what is computed from them is ggx_bulk_sample.h's.
#ifndef GGX_BULK_PARAMS_H
#define GGX_BULK_PARAMS_H

#include "ggx_kernel_io.h"
#include "ggx_bulk_sample.h"

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

#endif
