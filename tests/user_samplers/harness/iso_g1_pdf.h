// iso_g1_pdf.h - a negative control in an engine's style: exact anisotropic
// VNDF samples whose pdf takes the masking G1 of an isotropic surface at the
// mean roughness (ax + ay) / 2.  On an anisotropic surface the pdf is off by
// a constant factor: "the right shape with another normalization".
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

GGX_INLINE ggx_vec3 ggx_user_sample_m(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_heitz(i, ax, ay, u1, u2).m;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    const float a = 0.5f * (ax + ay);
    const ggx_vec3 h = ggx_normalize(ggx_add(i, o));
    return ggx_G1(i, a, a) * ggx_D(h, ax, ay) / (4.0f * i.z);
}
