// ggx_histogram.hlsl - ggx_histogram.comp in HLSL (glslang's HLSL front end
// through shaderc, GGX_HLSL=1): the same push constants and buffers, the same
// body (ggx_histogram_shader.h).
#include "ggx_contract.h"
#ifndef GGX_GROUP_SIZE
#define GGX_GROUP_SIZE 64
#endif
#define GGX_COUNTERS (GGX_BINS_Z * GGX_BINS_PHI + 2)

struct GgxBulkRequest {
    GGX_BULK_REQUEST_MEMBERS
};
// ConstantBuffer<T>: glslang puts a plain struct global with this attribute in $Global, a uniform buffer.
[[vk::push_constant]] ConstantBuffer<GgxBulkRequest> request;
[[vk::binding(1, 0)]] RWStructuredBuffer<uint> ggx_counts;
groupshared uint ggx_local_counts[GGX_COUNTERS];
#define GGX_LOCAL_ADD(index, value) InterlockedAdd(ggx_local_counts[index], value)
#define GGX_GLOBAL_ADD(index, value) InterlockedAdd(ggx_counts[index], value)
#define GGX_GROUP_BARRIER() GroupMemoryBarrierWithGroupSync()

#include "ggx_histogram_shader.h"

[numthreads(GGX_GROUP_SIZE, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    const uint i = id.y * request.row_width + id.x;
    ggx_shader_histogram(i / GGX_GROUP_SIZE, i % GGX_GROUP_SIZE);
}
