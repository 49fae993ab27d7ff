// engine_vndf_pdf_without_g1.hlsl - the same port with the bug ports of the
// VNDF pdf often have: the masking G1(V) left out of the density of L, so
// that it no longer integrates to 1 (it integrates to 1 / G1(V)).  The
// sampler is the engine's (engine_vndf.hlsl); only the pdf is wrong, and
// `ggx histogram --sampler` says which checks that fails and by how much.
#include "engine_vndf.hlsl"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

// The port's pdf: D(m) / (4 V.z), the visible normals' density without G1(V).
float EngineReflectionPdfWithoutG1(float3 V, float3 L, float2 alpha)
{
    float3 h = V + L;
    if (dot(h, h) <= 0.0f)
        return 0.0f;
    float3 m = normalize(h);
    if (dot(V, m) <= 0.0f)
        return 0.0f;
    return EngineGgxD(m, alpha) / (4.0f * V.z);
}

float3 ggx_user_sample_m(float3 i, float ax, float ay, float u1, float u2)
{
    return EngineSampleVisibleNormal(i, float2(ax, ay), float2(u1, u2));
}

float ggx_user_pdf(float3 i, float3 o, float ax, float ay)
{
    return EngineReflectionPdfWithoutG1(i, o, float2(ax, ay));
}
