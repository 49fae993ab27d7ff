// ggx_furnace.hlsl - ggx_furnace.comp in HLSL (glslang's HLSL front end
// through shaderc, GGX_HLSL=1): the same push constants and buffer, the same
// body (ggx_furnace_shader.h).
#include "ggx_contract.h"
#ifndef GGX_GROUP_SIZE
#define GGX_GROUP_SIZE 64
#endif

struct GgxBulkRequest {
    GGX_BULK_REQUEST_MEMBERS
};
// ConstantBuffer<T>: glslang puts a plain struct global with this attribute in $Global, a uniform buffer.
[[vk::push_constant]] ConstantBuffer<GgxBulkRequest> request;
[[vk::binding(1, 0)]] RWStructuredBuffer<float> outputs;

#include "ggx_furnace_shader.h"

[numthreads(GGX_GROUP_SIZE, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    ggx_shader_furnace(id.y * request.row_width + id.x);
}
