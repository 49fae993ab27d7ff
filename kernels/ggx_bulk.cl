// ggx_bulk.cl - bulk kernels: draw samples first .. first+count-1 of a seed
// into separate float arrays, and evaluate pdfs of given directions.
//
// The program is specialized by build options (set by the runtime):
//   GGX_METHOD=<id>                  which sampler (see ggx_samplers.h)
//   GGX_WRITE_{M,O,PDF_M,PDF_O,WEIGHT}=0|1   fields to compute and store
//   GGX_PER_SAMPLE_{VIEW,ALPHA,NORMAL}=0|1   parameters read per sample from buffers
// Arrays are planar: component c of sample j is at [c * stride + j].
// One sample per work-item; work-items past `count` recompute the last
// sample (same value, same address), so no branch breaks vectorization.
#include "ggx_samplers.h"

#ifndef GGX_METHOD
#error "build with -DGGX_METHOD=<method id>"
#endif
#ifndef GGX_WRITE_M
#define GGX_WRITE_M 0
#endif
#ifndef GGX_WRITE_O
#define GGX_WRITE_O 0
#endif
#ifndef GGX_WRITE_PDF_M
#define GGX_WRITE_PDF_M 0
#endif
#ifndef GGX_WRITE_PDF_O
#define GGX_WRITE_PDF_O 0
#endif
#ifndef GGX_WRITE_WEIGHT
#define GGX_WRITE_WEIGHT 0
#endif
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

__kernel void ggx_sample_bulk(ulong seed, ulong first, uint count, uint stride, GGX_PARAM_ARGS,
                              __global float* restrict m_out, __global float* restrict o_out,
                              __global float* restrict pdf_m_out, __global float* restrict pdf_o_out,
                              __global float* restrict weight_out)
{
    uint j = min((uint)get_global_id(0), count - 1u);
    ggx_params p = ggx_load_params(j, stride, GGX_PARAM_VALUES);
    float u1, u2;
    ggx_uniforms(seed, first + j, &u1, &u2);
    ggx_sample s = ggx_sample_method(GGX_METHOD, p.normal, p.view, p.ax, p.ay, u1, u2);
#if GGX_WRITE_M
    ggx_store3(m_out, j, stride, s.m);
#endif
#if GGX_WRITE_O
    ggx_store3(o_out, j, stride, s.o);
#endif
#if GGX_WRITE_PDF_M
    pdf_m_out[j] = s.pdf_m;
#endif
#if GGX_WRITE_PDF_O
    pdf_o_out[j] = s.pdf_o;
#endif
#if GGX_WRITE_WEIGHT
    weight_out[j] = s.weight;
#endif
}

// pdf of each given direction o (planar, `stride`) for the method's sampler.
__kernel void ggx_pdf_bulk(uint count, uint stride, GGX_PARAM_ARGS, __global const float* restrict o_in,
                           __global float* restrict pdf_out)
{
    uint j = min((uint)get_global_id(0), count - 1u);
    ggx_params p = ggx_load_params(j, stride, GGX_PARAM_VALUES);
    ggx_vec3 o = ggx_load3(o_in, j, stride);
    pdf_out[j] = ggx_pdf_method(GGX_METHOD, p.normal, p.view, o, p.ax, p.ay);
}
