// ggx_bulk.cl - bulk kernels: draw samples first .. first+count-1 of a seed
// into separate float arrays, and evaluate pdfs of given directions.
//
// The program is specialized by build options (set by the runtime):
//   GGX_METHOD=<id>                  which sampler (see ggx_samplers.h)
//   GGX_WRITE_{M,O,PDF_M,PDF_O,WEIGHT}=0|1   fields to compute and store
//   GGX_PER_SAMPLE_{VIEW,ALPHA,NORMAL}=0|1   parameters read per sample from buffers
//   GGX_ISOTROPIC=0|1, GGX_BELOW_HORIZON=0|1, GGX_WORLD_SPACE=0|1   what the request needs
// Arrays are planar: component c of sample j is at [c * stride + j].
// One sample per work-item; work-items past `count` recompute the last
// sample (same value, same address), so no branch breaks vectorization.
#ifndef GGX_METHOD
#error "build with -DGGX_METHOD=<method id>"
#endif
#include "ggx_bulk_params.h"
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

__kernel void ggx_sample_bulk(ulong seed, ulong first, uint count, uint stride, GGX_PARAM_ARGS,
                              __global float* restrict m_out, __global float* restrict o_out,
                              __global float* restrict pdf_m_out, __global float* restrict pdf_o_out,
                              __global float* restrict weight_out)
{
    uint j = min((uint)get_global_id(0), count - 1u);
    ggx_params p = ggx_load_params(j, stride, GGX_PARAM_VALUES);
    ggx_sample s = ggx_bulk_sample(seed, first + j, p);
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
    pdf_out[j] = ggx_bulk_pdf(p, o);
}
