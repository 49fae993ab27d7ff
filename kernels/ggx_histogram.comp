// ggx_histogram.comp - the histogram shader in GLSL 4.50 (Vulkan): the
// request (ggx_request_shader.h), the counters as a storage buffer and in
// shared memory, and ggx_histogram_shader.h's body per invocation.  The
// runtime compiles it with shaderc after "#version 450" and the variant's
// defines (as for ggx_histogram.cl) and GGX_GROUP_SIZE; ggx_histogram.hlsl
// is the same in HLSL.
#extension GL_GOOGLE_include_directive : require
#include "ggx_contract.h"
#define GGX_COUNTERS (GGX_BINS_Z * GGX_BINS_PHI + 2)

layout(std430, set = 0, binding = 1) buffer ggx_counts_block { uint ggx_counts[]; };
shared uint ggx_local_counts[GGX_COUNTERS];
#define GGX_LOCAL_ADD(index, value) atomicAdd(ggx_local_counts[index], value)
#define GGX_GLOBAL_ADD(index, value) atomicAdd(ggx_counts[index], value)
#define GGX_GROUP_BARRIER() barrier()

#include "ggx_histogram_shader.h"

GGX_COMPUTE_MAIN
{
    const uint i = GGX_INVOCATION;
    ggx_shader_histogram(i / GGX_GROUP_SIZE, i % GGX_GROUP_SIZE);
}
