// ggx_bulk_shader.h - the bulk sampling shader's body, one text for GLSL
// (ggx_bulk.comp) and HLSL (ggx_bulk.hlsl): per invocation what ggx_bulk.cl's
// ggx_sample_bulk does per work-item (and the pdf shader's, ggx_pdf.comp
// and .hlsl: what ggx_pdf_bulk does), with the same build switches
// (ggx_bulk_sample.h) and the same bits of every sample up to contraction.
// The including shader declares first `request` (push constants: the
// members of ggx_contract.h's GGX_BULK_REQUEST_MEMBERS), `inputs` (the per-sample planes) and
// `outputs` (the requested fields' planes), storage buffers of float.
// Planes are as in OpenCL: component c of sample j at [at + c * stride + j],
// `at` each buffer's offset in floats.  The dispatch is 2-D where a device
// caps work-groups per dimension: invocation (x, y) is sample
// y * row_width + x.
#ifndef GGX_BULK_SHADER_H
#define GGX_BULK_SHADER_H

#include "ggx_request_shader.h"

ggx_vec3 ggx_input3(ggx_uint at, ggx_uint j)
{
    const ggx_uint stride = request.stride;
    return ggx_vec3_make(inputs[at + j], inputs[at + stride + j], inputs[at + 2u * stride + j]);
}

void ggx_output3(ggx_uint at, ggx_uint j, ggx_vec3 v)
{
    const ggx_uint stride = request.stride;
    outputs[at + j] = v.x;
    outputs[at + stride + j] = v.y;
    outputs[at + 2u * stride + j] = v.z;
}

// The view, roughness, normal and relative index of sample j, and its
// caller's uniforms with GGX_PER_SAMPLE_UNIFORMS (ggx_load_params in OpenCL C).
ggx_params ggx_shader_params(ggx_uint j)
{
    ggx_params p = ggx_request_params();
#if GGX_PER_SAMPLE_VIEW
    p.view = ggx_input3(request.view_at, j);
#endif
#if GGX_PER_SAMPLE_ALPHA
    p.ax = inputs[request.alpha_at + j];
    p.ay = GGX_ISOTROPIC != 0 ? p.ax : inputs[request.alpha_at + request.stride + j];
#endif
#if GGX_PER_SAMPLE_NORMAL
    p.normal = ggx_input3(request.normal_at, j);
#endif
#if GGX_PER_SAMPLE_UNIFORMS
    p.u1 = inputs[request.uniforms_at + j];
    p.u2 = inputs[request.uniforms_at + request.stride + j];
    p.u3 = GGX_DIELECTRIC != 0 ? inputs[request.uniforms_at + 2u * request.stride + j] : 0.0f;
#endif
    return p;
}

// Sample `j` of the request (nothing past its count) into the requested fields.
void ggx_shader_sample_bulk(ggx_uint j)
{
    if (j >= request.count)
        return;
    const ggx_params p = ggx_bulk_uniforms(ggx_request_seed(), ggx_request_first(), j, ggx_shader_params(j));
    const ggx_sample s = ggx_bulk_sample_of(p);
#if GGX_WRITE_M
    ggx_output3(request.m_at, j, s.m);
#endif
#if GGX_WRITE_O
    ggx_output3(request.o_at, j, s.o);
#endif
#if GGX_WRITE_PDF_M
    outputs[request.pdf_m_at + j] = s.pdf_m;
#endif
#if GGX_WRITE_PDF_O
    outputs[request.pdf_o_at + j] = s.pdf_o;
#endif
#if GGX_WRITE_WEIGHT
    outputs[request.weight_at + j] = s.weight;
#endif
#if GGX_WRITE_U
    outputs[request.u_at + j] = p.u1;  // what the sample used, the caller's values as given
    outputs[request.u_at + request.stride + j] = p.u2;
#if GGX_DIELECTRIC
    outputs[request.u_at + 2u * request.stride + j] = p.u3;
#endif
#endif
}

// The pdf (GGX_EVAL=0) or the BSDF value f |cos| (GGX_EVAL=1) of direction j
// of the request, what ggx_bulk.cl's ggx_pdf_bulk computes: the directions'
// planes in `inputs` at request.o_at, the values into `outputs` at
// request.pdf_o_at.
void ggx_shader_pdf(ggx_uint j)
{
    if (j >= request.count)
        return;
    const ggx_params p = ggx_shader_params(j);
    const ggx_vec3 o = ggx_input3(request.o_at, j);
#if GGX_EVAL
    outputs[request.pdf_o_at + j] = ggx_bulk_eval(p, o);
#else
    outputs[request.pdf_o_at + j] = ggx_bulk_pdf(p, o);
#endif
}

#endif
