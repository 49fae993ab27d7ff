// furnace.hlsl - glsl/furnace.comp in HLSL: each invocation draws sample j
// of a GGX conductor (bounded VNDF sampling, Philox uniforms) in world space
// and stores its white-furnace weight and the difference between its pdf
// and the pdf recomputed from its direction.
//
// Build (glslang's HLSL front end, Vulkan 1.1):
//   glslangValidator -V -D -e main -S comp --target-env vulkan1.1 -DGGX_HLSL=1 \
//       -I<prefix>/include/ggxcl/cl furnace.hlsl -o furnace.spv
// (from the source tree: -Ikernels).  GGX_HLSL=1 tells the headers the
// language: glslang defines the same macros for GLSL and HLSL.
#include "ggx_world.h"

struct Surface {
    float4 normal_alpha;  // world-space normal, alpha
    float4 view;          // world-space view, pointing away from the surface
    uint seed, count;
};
[[vk::push_constant]] ConstantBuffer<Surface> surface;  // ConstantBuffer<T>: glslang needs it for a push constant block
[[vk::binding(0, 0)]] RWStructuredBuffer<float2> results;  // weight, pdf difference

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    uint j = id.x;
    if (j >= surface.count)
        return;
    float3 n = surface.normal_alpha.xyz, i = surface.view.xyz;
    float alpha = surface.normal_alpha.w;
    ggx_uniform_pair u = ggx_philox_pair(ggx_to_ulong(surface.seed), ggx_to_ulong(j));
    ggx_sample s = ggx_sample_world(GGX_METHOD_BOUNDED, n, i, alpha, u.u1, u.u2);
    float pdf = ggx_pdf_world(GGX_METHOD_BOUNDED, n, i, s.o, alpha);
    results[j] = float2(s.weight, abs(pdf - s.pdf_o));
}
