// ggx_bulk.cl - bulk kernels: draw samples first .. first+count-1 of a seed
// into separate float arrays, and evaluate pdfs of given directions.
//
// The program is specialized by build options (set by the runtime):
//   GGX_METHOD=<id>                  which sampler (see ggx_samplers.h)
//   GGX_WRITE_MASK=<bits>            fields to compute and store: bit 1 << GGX_FIELD_* (ggx_contract.h)
//   GGX_PER_SAMPLE_{VIEW,ALPHA,NORMAL,UNIFORMS}=0|1   parameters read per sample from buffers
//   GGX_SEQUENCE=<id>                where the uniforms come from otherwise (ggx_contract.h)
//   GGX_ISOTROPIC, GGX_BELOW_HORIZON, GGX_WORLD_SPACE, GGX_NORMAL_IS_Z=0|1   what the request needs
//   GGX_DIELECTRIC, GGX_IMPORTANCE=0|1  a rough dielectric of index eta, its transport (ggx_bulk_params.h)
//   GGX_EVAL=0|1                     the pdf kernels write the BSDF value f |cos| of o instead
// Arrays are planar: component c of sample j is at [offset + c * stride + j],
// each buffer with its own offset in floats (ulong arguments after the buffers).
// One sample per work-item.  Each kernel comes in two forms: the main one
// for whole work-groups, whose loads and stores go to consecutive addresses
// (PoCL vectorizes them as plain vector moves), and a `_tail` one for the
// last partial work-group, which clamps the index to count - 1: clamped
// addresses cost gathers and scatters, which is why the main form has none.
#ifndef GGX_METHOD
#error "build with -DGGX_METHOD=<method id>"
#endif
#include "ggx_bulk_params.h"

// Sample j (< count) into the requested fields.
GGX_INLINE void ggx_sample_into(ulong seed, ulong first, uint j, uint stride, GGX_PARAM_ARGS,
                                __global float* GGX_RESTRICT m_out, __global float* GGX_RESTRICT o_out,
                                __global float* GGX_RESTRICT pdf_m_out, __global float* GGX_RESTRICT pdf_o_out,
                                __global float* GGX_RESTRICT weight_out, __global float* GGX_RESTRICT u_out)
{
    ggx_params p = ggx_bulk_uniforms(seed, first, j, ggx_load_params(j, stride, GGX_PARAM_VALUES));
    ggx_sample s = ggx_bulk_sample_of(p);
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
#if GGX_WRITE_U
    u_out[j] = p.u1;  // what the sample used, the caller's values as given
    u_out[j + stride] = p.u2;
#if GGX_DIELECTRIC
    u_out[j + 2u * stride] = p.u3;
#endif
#endif
}

// The outputs follow the parameters, then each output's offset (ggx_contract.h).
#define GGX_SAMPLE_ARGS                                                                                 \
    ulong seed, ulong first, uint count, uint stride, GGX_PARAM_KERNEL_ARGS, __global float *GGX_RESTRICT m_out, \
        __global float *GGX_RESTRICT o_out, __global float *GGX_RESTRICT pdf_m_out, __global float *GGX_RESTRICT pdf_o_out, \
        __global float *GGX_RESTRICT weight_out, __global float *GGX_RESTRICT u_out, ulong m_at, ulong o_at,         \
        ulong pdf_m_at, ulong pdf_o_at, ulong weight_at, ulong u_at
#define GGX_SAMPLE_OUTPUTS_AT                                                                                  \
    m_out + m_at, o_out + o_at, pdf_m_out + pdf_m_at, pdf_o_out + pdf_o_at, weight_out + weight_at, u_out + u_at

// Whole work-groups of samples: every work-item is sample get_global_id(0) < count.
__kernel void ggx_sample_bulk(GGX_SAMPLE_ARGS)
{
    ggx_sample_into(seed, first, (uint)get_global_id(0), stride, GGX_PARAM_VALUES_AT, GGX_SAMPLE_OUTPUTS_AT);
}

// The last partial work-group (launched with a global offset): work-items
// past `count` redo the last sample, writing the same value to the same place.
__kernel void ggx_sample_bulk_tail(GGX_SAMPLE_ARGS)
{
    uint j = min((uint)get_global_id(0), count - 1u);
    ggx_sample_into(seed, first, j, stride, GGX_PARAM_VALUES_AT, GGX_SAMPLE_OUTPUTS_AT);
}

// pdf of each given direction o (planar, `stride`) for the method's sampler, or with GGX_EVAL its
// BSDF value.
GGX_INLINE void ggx_pdf_into(uint j, uint stride, GGX_PARAM_ARGS, __global const float* GGX_RESTRICT o_in,
                             __global float* GGX_RESTRICT pdf_out)
{
    ggx_params p = ggx_load_params(j, stride, GGX_PARAM_VALUES);
#if GGX_EVAL
    pdf_out[j] = ggx_bulk_eval(p, ggx_load3(o_in, j, stride));
#else
    pdf_out[j] = ggx_bulk_pdf(p, ggx_load3(o_in, j, stride));
#endif
}

#define GGX_PDF_ARGS                                                                                      \
    uint count, uint stride, GGX_PARAM_KERNEL_ARGS, __global const float *GGX_RESTRICT o_in,                \
        __global float *GGX_RESTRICT pdf_out, ulong o_at, ulong pdf_at

__kernel void ggx_pdf_bulk(GGX_PDF_ARGS)
{
    ggx_pdf_into((uint)get_global_id(0), stride, GGX_PARAM_VALUES_AT, o_in + o_at, pdf_out + pdf_at);
}

__kernel void ggx_pdf_bulk_tail(GGX_PDF_ARGS)
{
    ggx_pdf_into(min((uint)get_global_id(0), count - 1u), stride, GGX_PARAM_VALUES_AT, o_in + o_at, pdf_out + pdf_at);
}
