// ggx_histogram.hlsl - ggx_histogram.comp in HLSL (glslang's HLSL front end
// through shaderc, GGX_HLSL=1): the same request, counters and body.
#include "ggx_contract.h"
#define GGX_COUNTERS (GGX_BINS_Z * GGX_BINS_PHI + 2)

[[vk::binding(1, 0)]] RWStructuredBuffer<uint> ggx_counts;
groupshared uint ggx_local_counts[GGX_COUNTERS];
#define GGX_LOCAL_ADD(index, value) InterlockedAdd(ggx_local_counts[index], value)
#define GGX_GLOBAL_ADD(index, value) InterlockedAdd(ggx_counts[index], value)
#define GGX_GROUP_BARRIER() GroupMemoryBarrierWithGroupSync()

#include "ggx_histogram_shader.h"

GGX_COMPUTE_MAIN
{
    const uint i = GGX_INVOCATION;
    ggx_shader_histogram(i / GGX_GROUP_SIZE, i % GGX_GROUP_SIZE);
}
