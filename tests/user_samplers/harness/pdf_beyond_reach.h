// pdf_beyond_reach.h - a negative control: bounded's samples, with a pdf that
// is bounded's above the horizon and the plain VNDF's below it, where the
// sampler sends fewer samples (and discards them).  The samples follow the
// pdf where they go; the pdf holds mass beyond their reach, which the
// integral and the reach check must report.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_OWN

GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_bounded(i, ax, ay, u1, u2);
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return o.z > 0.0f ? ggx_pdf_bounded(i, o, ax, ay) : ggx_pdf_heitz(i, o, ax, ay);
}
