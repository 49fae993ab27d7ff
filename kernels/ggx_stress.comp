// ggx_stress.comp - the stress shader (`ggx stress --api vulkan`) in GLSL 4.50
// (Vulkan): the request (ggx_request_shader.h), the planes
// (ggx_planes_shader.h) and ggx_stress_shader.h's body per invocation.  The
// runtime compiles it with shaderc after "#version 450" and its defines (those
// of the OpenCL program, ggx_stress.cl) and GGX_GROUP_SIZE; ggx_stress.hlsl is
// the same in HLSL.
#extension GL_GOOGLE_include_directive : require
#include "ggx_planes_shader.h"
#include "ggx_stress_shader.h"

GGX_COMPUTE_MAIN
{
    ggx_shader_stress(GGX_INVOCATION);
}
