// ggx_stress.hlsl - ggx_stress.comp in HLSL (glslang's HLSL front end through
// shaderc, GGX_HLSL=1): the same request, planes and body.
#include "ggx_planes_shader.h"
#include "ggx_stress_shader.h"

GGX_COMPUTE_MAIN
{
    ggx_shader_stress(GGX_INVOCATION);
}
