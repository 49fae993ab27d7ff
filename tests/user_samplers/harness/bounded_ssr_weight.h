// bounded_ssr_weight.h - a negative control in the style of a screen-space
// reflection pass: bounded's samples and pdf, weighted with the plain VNDF's
// weight G2(i, o) / G1(i), which belongs to another distribution.  The mean
// weight must differ from the albedo, and the check name the ratio.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_OWN

GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    ggx_sample s = ggx_sample_bounded(i, ax, ay, u1, u2);
    s.weight = s.o.z > 0.0f ? ggx_G2(i, s.o, ax, ay) / ggx_G1(i, ax, ay) : 0.0f;
    return s;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return ggx_pdf_bounded(i, o, ax, ay);
}
