// vndf_pdf_over_vh.h - a negative control in an engine's style: exact VNDF
// samples whose reflection pdf is written D(h) / (4 V.H), where the VNDF's is
// G1(V) D(h) / (4 N.V).  The ratio to the right pdf varies over the samples:
// "the shape differs".
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

GGX_INLINE ggx_vec3 ggx_user_sample_m(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_heitz(i, ax, ay, u1, u2).m;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    const ggx_vec3 h = ggx_normalize(ggx_add(i, o));
    return ggx_D(h, ax, ay) / (4.0f * ggx_fabs(ggx_dot(i, h)));
}
