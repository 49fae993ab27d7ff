// ggx_pdf.hlsl - ggx_pdf.comp in HLSL (glslang's HLSL front end through
// shaderc, GGX_HLSL=1): the same request, planes and body.
#include "ggx_planes_shader.h"
#include "ggx_bulk_shader.h"

GGX_COMPUTE_MAIN
{
    ggx_shader_pdf(GGX_INVOCATION);
}
