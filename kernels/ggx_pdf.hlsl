// ggx_pdf.hlsl - ggx_pdf.comp in HLSL (glslang's HLSL front end through
// shaderc, GGX_HLSL=1): the same push constants and buffers, the same body
// (ggx_bulk_shader.h's ggx_shader_pdf).
#include "ggx_contract.h"
#ifndef GGX_GROUP_SIZE
#define GGX_GROUP_SIZE 64
#endif

struct GgxBulkRequest {
    GGX_BULK_REQUEST_MEMBERS
};
// ConstantBuffer<T>: glslang puts a plain struct global with this attribute in $Global, a uniform buffer.
[[vk::push_constant]] ConstantBuffer<GgxBulkRequest> request;
[[vk::binding(0, 0)]] StructuredBuffer<float> inputs;
[[vk::binding(1, 0)]] RWStructuredBuffer<float> outputs;

#include "ggx_bulk_shader.h"

[numthreads(GGX_GROUP_SIZE, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    ggx_shader_pdf(id.y * request.row_width + id.x);
}
