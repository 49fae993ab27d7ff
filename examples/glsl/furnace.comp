// furnace.comp - ggxcl's samplers in a GLSL compute shader for Vulkan: each
// invocation draws sample j of a GGX conductor (bounded VNDF sampling, its
// uniforms from Philox), in world space about the surface normal, and
// stores its white-furnace weight (the mean over all samples estimates the
// directional albedo) and the difference between its pdf and the pdf that
// the method's pdf function recomputes from the direction (MIS needs both).
//
// Build: glslangValidator -V -I<prefix>/include/ggxcl/cl furnace.comp -o furnace.spv
// (from the source tree: -Ikernels); the shader needs shaderInt64 for Philox.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "ggx_world.h"

layout(local_size_x = 64) in;
layout(push_constant) uniform Surface {
    vec4 normal_alpha;  // world-space normal, alpha
    vec4 view;          // world-space view, pointing away from the surface
    uint seed, count;
} surface;
layout(std430, binding = 0) writeonly buffer Results { vec2 results[]; };  // weight, pdf difference

void main()
{
    uint j = gl_GlobalInvocationID.x;
    if (j >= surface.count)
        return;
    vec3 n = surface.normal_alpha.xyz, i = surface.view.xyz;
    float alpha = surface.normal_alpha.w;
    ggx_uniform_pair u = ggx_philox_pair(ggx_to_ulong(surface.seed), ggx_to_ulong(j));
    ggx_sample s = ggx_sample_world(GGX_METHOD_BOUNDED, n, i, alpha, u.u1, u.u2);
    float pdf = ggx_pdf_world(GGX_METHOD_BOUNDED, n, i, s.o, alpha);
    results[j] = vec2(s.weight, abs(pdf - s.pdf_o));
}
