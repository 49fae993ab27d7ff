// bounded_discards_m.h - the same rejection as a sampler of m alone: bounded's
// normal, a pdf of 0 below the horizon (the completion gives those samples
// weight 0).  Must pass every check.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_OWN

GGX_INLINE ggx_vec3 ggx_user_sample_m(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_bounded(i, ax, ay, u1, u2).m;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return o.z > 0.0f ? ggx_pdf_bounded(i, o, ax, ay) : 0.0f;
}
