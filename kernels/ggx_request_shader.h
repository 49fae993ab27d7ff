// ggx_request_shader.h - what every compute shader (GLSL and HLSL) reads of
// its request, the push constants of ggx_contract.h's
// GGX_BULK_REQUEST_MEMBERS: the 64-bit seed and first index from their
// 32-bit words, and the uniform view, roughness, normal and relative index
// as ggx_params (ggx_bulk_sample.h) with no uniforms yet.  The including
// shader declares `request` first.
#ifndef GGX_REQUEST_SHADER_H
#define GGX_REQUEST_SHADER_H

#include "ggx_bulk_sample.h"

ggx_ulong ggx_request_words(ggx_uint lo, ggx_uint hi)
{
    return (ggx_to_ulong(hi) << 32) | ggx_to_ulong(lo);
}

ggx_ulong ggx_request_seed() { return ggx_request_words(request.seed_lo, request.seed_hi); }
ggx_ulong ggx_request_first() { return ggx_request_words(request.first_lo, request.first_hi); }

// The request's uniform parameters (GGX_ISOTROPIC: alpha_x for both; GGX_NORMAL_IS_Z: +z exactly).
ggx_params ggx_request_params()
{
    ggx_params p;
    p.view = ggx_vec3_make(request.view_x, request.view_y, request.view_z);
    p.ax = request.alpha_x;
    p.ay = GGX_ISOTROPIC != 0 ? request.alpha_x : request.alpha_y;
#if GGX_NORMAL_IS_Z
    p.normal = ggx_vec3_make(0.0f, 0.0f, 1.0f);
#else
    p.normal = ggx_vec3_make(request.normal_x, request.normal_y, request.normal_z);
#endif
    p.eta = request.eta;
    p.u1 = 0.0f;
    p.u2 = 0.0f;
    p.u3 = 0.0f;
    return p;
}

#endif
