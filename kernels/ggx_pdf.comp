// ggx_pdf.comp - the pdf and BSDF shader in GLSL 4.50 (Vulkan): the
// request as push constants, the inputs and outputs as storage buffers, and
// ggx_bulk_shader.h's ggx_shader_pdf per invocation.  The runtime compiles it with
// shaderc after "#version 450" and the variant's defines (GGX_METHOD,
// GGX_EVAL, ... as for ggx_bulk.cl's ggx_pdf_bulk) and GGX_GROUP_SIZE.
#extension GL_GOOGLE_include_directive : require
#include "ggx_contract.h"
#ifndef GGX_GROUP_SIZE
#define GGX_GROUP_SIZE 64
#endif

layout(local_size_x = GGX_GROUP_SIZE) in;
layout(push_constant) uniform GgxBulkRequest { GGX_BULK_REQUEST_MEMBERS } request;
layout(std430, set = 0, binding = 0) readonly buffer GgxInputs { float inputs[]; };
layout(std430, set = 0, binding = 1) writeonly buffer GgxOutputs { float outputs[]; };

#include "ggx_bulk_shader.h"

void main()
{
    ggx_shader_pdf(gl_GlobalInvocationID.y * request.row_width + gl_GlobalInvocationID.x);
}
