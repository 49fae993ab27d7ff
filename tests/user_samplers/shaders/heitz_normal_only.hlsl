// heitz_normal_only.hlsl - an HLSL user sampler that returns m alone
// (Heitz 2018's normal); the library completes o, the densities and the
// weight from it and this pdf.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

float3 ggx_user_sample_m(float3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_heitz(i, ax, ay, u1, u2).m;
}

float ggx_user_pdf(float3 i, float3 o, float ax, float ay)
{
    return ggx_pdf_heitz(i, o, ax, ay);
}
