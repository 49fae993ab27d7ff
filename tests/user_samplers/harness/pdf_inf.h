// pdf_inf.h - a negative control: heitz's samples with a pdf of +infinity
// everywhere.  No check may pass on it for want of evidence.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    ggx_sample s = ggx_sample_heitz(i, ax, ay, u1, u2);
    s.pdf_o = INFINITY;
    return s;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return INFINITY;
}
