// wider_lobe.h - a negative control that differs from its pdf only in theta
// at V = N: heitz's normals drawn at 1.02 times the roughness the pdf is
// evaluated at.  At alpha 0.05 the histogram's top ring holds nearly the
// whole lobe; the rings of equal mass in theta must reject it.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

GGX_INLINE ggx_vec3 ggx_user_sample_m(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_heitz(i, 1.02f * ax, 1.02f * ay, u1, u2).m;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return ggx_pdf_heitz(i, o, ax, ay);
}
