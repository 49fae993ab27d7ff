// ggx_request_shader.h - what every compute shader of the runtime (GLSL and
// HLSL) shares: its work-group size (GGX_GROUP_SIZE, default 64), its
// request as push constants, `ggx_request` (the members of ggx_contract.h's
// GGX_BULK_REQUEST_MEMBERS, from which the runtime makes its struct), the
// entry point (GGX_COMPUTE_MAIN, then a body that reads GGX_INVOCATION, the
// invocation y * row_width + x of the 2-D dispatch), and what it reads of
// the request: the 64-bit seed and first index from their 32-bit words, and
// the uniform view, roughness, normal and relative index as ggx_params
// (ggx_bulk_sample.h) with no uniforms yet.
#ifndef GGX_REQUEST_SHADER_H
#define GGX_REQUEST_SHADER_H

#include "ggx_contract.h"
#ifndef GGX_GROUP_SIZE
#define GGX_GROUP_SIZE 64
#endif

#if defined(GGX_HLSL) || defined(__HLSL_VERSION)
struct ggx_bulk_request {
    GGX_BULK_REQUEST_MEMBERS
};
// ConstantBuffer<T>: glslang puts a plain struct global with this attribute in $Global, a uniform buffer.
[[vk::push_constant]] ConstantBuffer<ggx_bulk_request> ggx_request;
#define GGX_COMPUTE_MAIN [numthreads(GGX_GROUP_SIZE, 1, 1)] void main(uint3 ggx_id : SV_DispatchThreadID)
#define GGX_INVOCATION (ggx_id.y * ggx_request.row_width + ggx_id.x)
#else
layout(local_size_x = GGX_GROUP_SIZE) in;
layout(push_constant) uniform ggx_bulk_request { GGX_BULK_REQUEST_MEMBERS } ggx_request;
#define GGX_COMPUTE_MAIN void main()
#define GGX_INVOCATION (gl_GlobalInvocationID.y * ggx_request.row_width + gl_GlobalInvocationID.x)
#endif

#include "ggx_bulk_sample.h"

ggx_ulong ggx_request_words(ggx_uint lo, ggx_uint hi)
{
    return (ggx_to_ulong(hi) << 32) | ggx_to_ulong(lo);
}

ggx_ulong ggx_request_seed() { return ggx_request_words(ggx_request.seed_lo, ggx_request.seed_hi); }
ggx_ulong ggx_request_first() { return ggx_request_words(ggx_request.first_lo, ggx_request.first_hi); }

// The request's uniform parameters (GGX_ISOTROPIC: alpha_x for both; GGX_NORMAL_IS_Z: +z exactly).
ggx_params ggx_request_params()
{
    ggx_params p;
    p.view = ggx_vec3_make(ggx_request.view_x, ggx_request.view_y, ggx_request.view_z);
    p.ax = ggx_request.alpha_x;
    p.ay = GGX_ISOTROPIC != 0 ? ggx_request.alpha_x : ggx_request.alpha_y;
#if GGX_NORMAL_IS_Z
    p.normal = ggx_vec3_make(0.0f, 0.0f, 1.0f);
#else
    p.normal = ggx_vec3_make(ggx_request.normal_x, ggx_request.normal_y, ggx_request.normal_z);
#endif
    p.eta = ggx_request.eta;
    p.u1 = 0.0f;
    p.u2 = 0.0f;
    p.u3 = 0.0f;
    return p;
}

#endif
