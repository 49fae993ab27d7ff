// undeclared_name.hlsl - a negative control: line 9 calls a function that
// does not exist; the error must name this file and that line.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

ggx_sample ggx_user_sample(float3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_capz(i, ax, ay, u1, u2);
}

float ggx_user_pdf(float3 i, float3 o, float ax, float ay)
{
    return ggx_pdf_caps(i, o, ax, ay);
}
