// pdf_zero_kept.h - a negative control: heitz's samples whose pdf is set to 0
// below the horizon while their weight is left at 1 (kept samples without a
// density).  Must fail the pdf checks, naming the count.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    ggx_sample s = ggx_sample_heitz(i, ax, ay, u1, u2);
    if (s.o.z <= 0.0f) {
        s.pdf_o = 0.0f;
        s.weight = 1.0f;
    }
    return s;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return o.z > 0.0f ? ggx_pdf_heitz(i, o, ax, ay) : 0.0f;
}
