// ggx_bulk.comp - the bulk sampling shader in GLSL 4.50 (Vulkan): the request
// (ggx_request_shader.h), the planes (ggx_planes_shader.h) and
// ggx_bulk_shader.h's body per invocation.  The runtime compiles it with
// shaderc after "#version 450" and its defines (those of the OpenCL program,
// ggx_bulk.cl) and GGX_GROUP_SIZE; ggx_bulk.hlsl is the same in HLSL.
#extension GL_GOOGLE_include_directive : require
#include "ggx_planes_shader.h"
#include "ggx_bulk_shader.h"

GGX_COMPUTE_MAIN
{
    ggx_shader_sample_bulk(GGX_INVOCATION);
}
