// engine_direction_check.hlsl - the adapter for an engine function that
// returns the outgoing direction and its pdf (EngineSampleReflection): it
// fills the whole ggx_sample.  m is the half vector of V and L, pdf_m the
// pdf of L times the reflection's Jacobian 4 |V.m|, the weight the GGX
// BRDF's f |L.z| / pdf (Fresnel 1; ggxcl's ggx_eval_reflection), 0 where
// the pdf is 0.
#include "engine_vndf.hlsl"
#define GGX_USER_DISTRIBUTION GGX_USER_VNDF     // what the engine claims to sample

ggx_sample ggx_user_sample(float3 i, float ax, float ay, float u1, float u2)
{
    float pdf;
    const float3 o = EngineSampleReflection(i, float2(ax, ay), float2(u1, u2), pdf);
    ggx_sample s;
    s.m = normalize(i + o);
    s.o = o;
    s.pdf_o = pdf;
    s.pdf_m = 4.0f * abs(dot(i, s.m)) * pdf;
    s.weight = pdf > 0.0f ? ggx_eval_reflection(i, o, ax, ay) / pdf : 0.0f;
    return s;
}

float ggx_user_pdf(float3 i, float3 o, float ax, float ay)
{
    return EngineReflectionPdf(i, o, float2(ax, ay));
}
