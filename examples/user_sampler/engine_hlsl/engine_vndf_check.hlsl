// engine_vndf_check.hlsl - the adapter that puts the engine's own sampler
// (engine_vndf.hlsl, unchanged) through ggxcl's checks: three lines of the
// user-sampler contract (docs/USER-SAMPLERS.md) over its functions.
//   ggx histogram --sampler examples/user_sampler/engine_hlsl/engine_vndf_check.hlsl --check 1e-3 --out out/engine
#include "engine_vndf.hlsl"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

float3 ggx_user_sample_m(float3 i, float ax, float ay, float u1, float u2)
{
    return EngineSampleVisibleNormal(i, float2(ax, ay), float2(u1, u2));
}

float ggx_user_pdf(float3 i, float3 o, float ax, float ay)
{
    return EngineReflectionPdf(i, o, float2(ax, ay));
}
