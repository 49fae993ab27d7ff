// ggx_furnace.hlsl - ggx_furnace.comp in HLSL (glslang's HLSL front end through
// shaderc, GGX_HLSL=1): the same request, planes and body.
#include "ggx_planes_shader.h"
#include "ggx_furnace_shader.h"

GGX_COMPUTE_MAIN
{
    ggx_shader_furnace(GGX_INVOCATION);
}
