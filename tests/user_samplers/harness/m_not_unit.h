// m_not_unit.h - heitz's normal returned 0.05 % longer than unit (as an fp16
// normal may be): the completion normalizes it before it reflects, so every
// check must pass.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

GGX_INLINE ggx_vec3 ggx_user_sample_m(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_scale(ggx_sample_heitz(i, ax, ay, u1, u2).m, 1.0005f);
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return ggx_pdf_heitz(i, o, ax, ay);
}
