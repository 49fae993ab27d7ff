// ggx_stress.comp - the stress shader in GLSL 4.50 (Vulkan; `ggx stress
// --api vulkan`): the request as push constants, the cases' inputs and
// outputs as storage buffers, and ggx_stress_shader.h's body per
// invocation.  The runtime compiles it with shaderc after "#version 450"
// and the defines of ggx_stress.cl (GGX_METHOD, GGX_GUARDS, GGX_DIELECTRIC)
// and GGX_GROUP_SIZE.
#extension GL_GOOGLE_include_directive : require
#include "ggx_contract.h"
#ifndef GGX_GROUP_SIZE
#define GGX_GROUP_SIZE 64
#endif

layout(local_size_x = GGX_GROUP_SIZE) in;
layout(push_constant) uniform GgxBulkRequest { GGX_BULK_REQUEST_MEMBERS } request;
layout(std430, set = 0, binding = 0) readonly buffer GgxInputs { float inputs[]; };
layout(std430, set = 0, binding = 1) writeonly buffer GgxOutputs { float outputs[]; };

#include "ggx_stress_shader.h"

void main()
{
    ggx_shader_stress(gl_GlobalInvocationID.y * request.row_width + gl_GlobalInvocationID.x);
}
