// ggx_furnace_shader.h - the fused white-furnace shader's body, one text for
// GLSL (ggx_furnace.comp) and HLSL (ggx_furnace.hlsl): per invocation what
// ggx_furnace.cl's ggx_furnace_bulk does per work-item, with the same build
// switches and the same samples per invocation (GGX_FURNACE_PER_ITEM), so
// that the partial sums do not depend on how a range is split into
// dispatches that start at multiples of it.
// The including shader declares first `ggx_outputs` (ggx_planes_shader.h);
// ggx_request.stride is the invocations that write sums: sums[item] = the sum of its
// weights, sums[items + item] = of their squares, and with GGX_DIELECTRIC
// sums[2 items + item] = of its reflected samples' weights.
#ifndef GGX_FURNACE_SHADER_H
#define GGX_FURNACE_SHADER_H

#include "ggx_request_shader.h"

// Invocation `item` sums samples GGX_FURNACE_PER_ITEM * item + k (k < GGX_FURNACE_PER_ITEM) below count.
void ggx_shader_furnace(ggx_uint item)
{
    const ggx_uint items = ggx_request.stride;
    if (item >= items)
        return;
    const ggx_params p = ggx_request_params();
    const ggx_ulong seed = ggx_request_seed(), first = ggx_request_first();
    float w_total = 0.0f, w2_total = 0.0f, reflected_total = 0.0f;
    for (ggx_uint k = 0u; k < ggx_to_uint(GGX_FURNACE_PER_ITEM); ++k) {
        const ggx_uint index = item * ggx_to_uint(GGX_FURNACE_PER_ITEM) + k;
        if (index >= ggx_request.count)
            break;
        const ggx_sample s = ggx_bulk_sample(seed, first, index, p);
        w_total += s.weight;
        w2_total += s.weight * s.weight;
#if GGX_DIELECTRIC
        reflected_total += ggx_bulk_reflected(p, s) ? s.weight : 0.0f;
#endif
    }
    ggx_outputs[item] = w_total;
    ggx_outputs[items + item] = w2_total;
#if GGX_DIELECTRIC
    ggx_outputs[2u * items + item] = reflected_total;
#else
    GGX_UNUSED(reflected_total);
#endif
}

#endif
