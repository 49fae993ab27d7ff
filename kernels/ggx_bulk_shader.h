// ggx_bulk_shader.h - the bulk sampling shader's body, one text for GLSL
// (ggx_bulk.comp) and HLSL (ggx_bulk.hlsl): per invocation what ggx_bulk.cl's
// ggx_sample_bulk does per work-item (and the pdf shader's, ggx_pdf.comp
// and .hlsl: what ggx_pdf_bulk does), with the same build switches
// (ggx_bulk_sample.h) and the same bits of every sample up to contraction.
// The including shader declares first `ggx_inputs` (the per-sample planes) and
// `ggx_outputs` (the requested fields' planes): ggx_planes_shader.h.  Planes
// are as in OpenCL: component c of sample j at [at + c * stride + j], `at`
// each buffer's offset in floats.  The dispatch is 2-D where a device
// caps work-groups per dimension: invocation (x, y) is sample
// y * row_width + x.
#ifndef GGX_BULK_SHADER_H
#define GGX_BULK_SHADER_H

#include "ggx_request_shader.h"

ggx_vec3 ggx_input3(ggx_uint at, ggx_uint j)
{
    const ggx_uint stride = ggx_request.stride;
    return ggx_vec3_make(ggx_inputs[at + j], ggx_inputs[at + stride + j], ggx_inputs[at + 2u * stride + j]);
}

void ggx_output3(ggx_uint at, ggx_uint j, ggx_vec3 v)
{
    const ggx_uint stride = ggx_request.stride;
    ggx_outputs[at + j] = v.x;
    ggx_outputs[at + stride + j] = v.y;
    ggx_outputs[at + 2u * stride + j] = v.z;
}

// The view, roughness, normal and relative index of sample j, and its
// caller's uniforms with GGX_PER_SAMPLE_UNIFORMS (ggx_load_params in OpenCL C).
ggx_params ggx_shader_params(ggx_uint j)
{
    ggx_params p = ggx_request_params();
#if GGX_PER_SAMPLE_VIEW
    p.view = ggx_input3(ggx_request.view_at, j);
#endif
#if GGX_PER_SAMPLE_ALPHA
    p.ax = ggx_inputs[ggx_request.alpha_at + j];
    p.ay = GGX_ISOTROPIC != 0 ? p.ax : ggx_inputs[ggx_request.alpha_at + ggx_request.stride + j];
#endif
#if GGX_PER_SAMPLE_NORMAL
    p.normal = ggx_input3(ggx_request.normal_at, j);
#endif
#if GGX_PER_SAMPLE_UNIFORMS
    p.u1 = ggx_inputs[ggx_request.uniforms_at + j];
    p.u2 = ggx_inputs[ggx_request.uniforms_at + ggx_request.stride + j];
    p.u3 = GGX_DIELECTRIC != 0 ? ggx_inputs[ggx_request.uniforms_at + 2u * ggx_request.stride + j] : 0.0f;
#endif
    return p;
}

// Sample `j` of the request (nothing past its count) into the requested fields.
void ggx_shader_sample_bulk(ggx_uint j)
{
    if (j >= ggx_request.count)
        return;
    const ggx_params p = ggx_bulk_uniforms(ggx_request_seed(), ggx_request_first(), j, ggx_shader_params(j));
    const ggx_sample s = ggx_bulk_sample_of(p);
#if GGX_WRITE_M
    ggx_output3(ggx_request.m_at, j, s.m);
#endif
#if GGX_WRITE_O
    ggx_output3(ggx_request.o_at, j, s.o);
#endif
#if GGX_WRITE_PDF_M
    ggx_outputs[ggx_request.pdf_m_at + j] = s.pdf_m;
#endif
#if GGX_WRITE_PDF_O
    ggx_outputs[ggx_request.pdf_o_at + j] = s.pdf_o;
#endif
#if GGX_WRITE_WEIGHT
    ggx_outputs[ggx_request.weight_at + j] = s.weight;
#endif
#if GGX_WRITE_U
    ggx_outputs[ggx_request.u_at + j] = p.u1;  // what the sample used, the caller's values as given
    ggx_outputs[ggx_request.u_at + ggx_request.stride + j] = p.u2;
#if GGX_DIELECTRIC
    ggx_outputs[ggx_request.u_at + 2u * ggx_request.stride + j] = p.u3;
#endif
#endif
}

// The pdf (GGX_EVAL=0) or the BSDF value f |cos| (GGX_EVAL=1) of direction j
// of the request, what ggx_bulk.cl's ggx_pdf_bulk computes: the directions'
// planes in `ggx_inputs` at ggx_request.o_at, the values into `ggx_outputs` at
// ggx_request.pdf_o_at.
void ggx_shader_pdf(ggx_uint j)
{
    if (j >= ggx_request.count)
        return;
    const ggx_params p = ggx_shader_params(j);
    const ggx_vec3 o = ggx_input3(ggx_request.o_at, j);
#if GGX_EVAL
    ggx_outputs[ggx_request.pdf_o_at + j] = ggx_bulk_eval(p, o);
#else
    ggx_outputs[ggx_request.pdf_o_at + j] = ggx_bulk_pdf(p, o);
#endif
}

#endif
