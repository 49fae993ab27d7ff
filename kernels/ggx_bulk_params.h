// ggx_bulk_params.h - what the bulk kernels share: planar loads and stores,
// and the view, roughness and normal of sample j, uniform or per sample
// (build options GGX_PER_SAMPLE_{VIEW,ALPHA,NORMAL}=0|1).
#ifndef GGX_BULK_PARAMS_H
#define GGX_BULK_PARAMS_H

#include "ggx_samplers.h"

#ifndef GGX_PER_SAMPLE_VIEW
#define GGX_PER_SAMPLE_VIEW 0
#endif
#ifndef GGX_PER_SAMPLE_ALPHA
#define GGX_PER_SAMPLE_ALPHA 0
#endif
#ifndef GGX_PER_SAMPLE_NORMAL
#define GGX_PER_SAMPLE_NORMAL 0
#endif

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

// The kernel arguments that carry them: uniform values, then per-sample buffers.
#define GGX_PARAM_ARGS                                                                      \
    float view_x, float view_y, float view_z, float alpha_x, float alpha_y, float normal_x, \
        float normal_y, float normal_z, __global const float *restrict view_in,             \
        __global const float *restrict alpha_in, __global const float *restrict normal_in
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
    p.ay = alpha_in[j + stride];
#else
    p.ax = alpha_x;
    p.ay = alpha_y;
#endif
#if GGX_PER_SAMPLE_NORMAL
    p.normal = ggx_load3(normal_in, j, stride);
#else
    p.normal = ggx_vec3_make(normal_x, normal_y, normal_z);
#endif
    return p;
}

#endif
