// ggx_stress_shader.h - the stress shader's body, one text for GLSL
// (ggx_stress.comp) and HLSL (ggx_stress.hlsl): per invocation what
// ggx_stress.cl does per work-item (ggx_stress_case.h), with the same layout
// of planar inputs and outputs.  The including shader declares first
// `ggx_inputs` and `ggx_outputs` (ggx_planes_shader.h); of the request it reads
// `count`.
#ifndef GGX_STRESS_SHADER_H
#define GGX_STRESS_SHADER_H

#include "ggx_request_shader.h"
#include "ggx_stress_case.h"

void ggx_shader_stress(ggx_uint j)
{
    const ggx_uint count = ggx_request.count;
    if (j >= count)
        return;
    ggx_stress_input c;
    c.ax = ggx_inputs[j];
    c.ay = ggx_inputs[count + j];
    c.i = ggx_vec3_make(ggx_inputs[2u * count + j], ggx_inputs[3u * count + j], ggx_inputs[4u * count + j]);
    c.n = ggx_vec3_make(ggx_inputs[5u * count + j], ggx_inputs[6u * count + j], ggx_inputs[7u * count + j]);
    c.u1 = ggx_inputs[8u * count + j];
    c.u2 = ggx_inputs[9u * count + j];
#if GGX_DIELECTRIC
    c.u3 = ggx_inputs[10u * count + j];
    c.eta = ggx_inputs[11u * count + j];
#else
    c.u3 = 0.0f;
    c.eta = 1.0f;
#endif
    const ggx_stress_result r = ggx_stress_case(c);
    for (ggx_uint k = 0u; k < GGX_STRESS_OUTPUTS; ++k)
        ggx_outputs[k * count + j] = ggx_stress_output(r, k);
}

#endif
