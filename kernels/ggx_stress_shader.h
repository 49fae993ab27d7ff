// ggx_stress_shader.h - the stress shader's body, one text for GLSL
// (ggx_stress.comp) and HLSL (ggx_stress.hlsl): per invocation what
// ggx_stress.cl does per work-item (ggx_stress_case.h), with the same layout
// of planar inputs and outputs.  The including shader declares first
// `request` (push constants: GGX_BULK_REQUEST_MEMBERS, of which it reads
// `count`), `inputs` and `outputs`, storage buffers of float.
#ifndef GGX_STRESS_SHADER_H
#define GGX_STRESS_SHADER_H

#include "ggx_stress_case.h"

void ggx_shader_stress(ggx_uint j)
{
    const ggx_uint count = request.count;
    if (j >= count)
        return;
    ggx_stress_input c;
    c.ax = inputs[j];
    c.ay = inputs[count + j];
    c.i = ggx_vec3_make(inputs[2u * count + j], inputs[3u * count + j], inputs[4u * count + j]);
    c.n = ggx_vec3_make(inputs[5u * count + j], inputs[6u * count + j], inputs[7u * count + j]);
    c.u1 = inputs[8u * count + j];
    c.u2 = inputs[9u * count + j];
#if GGX_DIELECTRIC
    c.u3 = inputs[10u * count + j];
    c.eta = inputs[11u * count + j];
#else
    c.u3 = 0.0f;
    c.eta = 1.0f;
#endif
    const ggx_stress_result r = ggx_stress_case(c);
    for (ggx_uint k = 0u; k < GGX_STRESS_OUTPUTS; ++k)
        outputs[k * count + j] = ggx_stress_output(r, k);
}

#endif
