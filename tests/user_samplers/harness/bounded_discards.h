// bounded_discards.h - an engine's rejection: bounded's cap, and the samples
// that reflect below the horizon returned with weight 0 and pdf 0, the pdf 0
// there too.  Right for a renderer: must pass every check.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_OWN

GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    ggx_sample s = ggx_sample_bounded(i, ax, ay, u1, u2);
    if (s.o.z <= 0.0f) {
        s.pdf_o = 0.0f;
        s.pdf_m = 0.0f;
        s.weight = 0.0f;
    }
    return s;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return o.z > 0.0f ? ggx_pdf_bounded(i, o, ax, ay) : 0.0f;
}
