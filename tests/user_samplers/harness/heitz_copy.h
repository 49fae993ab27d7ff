// heitz_copy.h - heitz as a user sampler (claims the VNDF): must pass every check.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_heitz(i, ax, ay, u1, u2);
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return ggx_pdf_heitz(i, o, ax, ay);
}
