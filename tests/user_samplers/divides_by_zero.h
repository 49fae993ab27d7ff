// divides_by_zero.h - a negative control: caps whose weight is divided by
// ax - ay, zero on an isotropic surface, where its samples must show
// non-finite values in the stability map.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    ggx_sample s = ggx_sample_caps(i, ax, ay, u1, u2);
    s.weight = s.weight * (ax - ay + 1.0f) / (ax - ay);
    return s;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return ggx_pdf_caps(i, o, ax, ay);
}
