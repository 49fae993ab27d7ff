// pdf_not_a_density.h - a negative control: heitz's samples with a pdf that
// is no density at all, the same everywhere for a given roughness: NaN for
// ax < 0.45, +infinity for 0.45 <= ax < 0.55, 0 from 0.55 (one file for the
// three, each run at its own --alpha).  No check may pass on it for want of
// evidence.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

GGX_INLINE float ggx_not_a_density(float ax)
{
    return ax < 0.45f ? NAN : (ax < 0.55f ? INFINITY : 0.0f);
}

GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    ggx_sample s = ggx_sample_heitz(i, ax, ay, u1, u2);
    s.pdf_o = ggx_not_a_density(ax);
    return s;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    GGX_UNUSED(i);
    GGX_UNUSED(o);
    GGX_UNUSED(ay);
    return ggx_not_a_density(ax);
}
