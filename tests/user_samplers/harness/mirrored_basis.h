// mirrored_basis.h - a negative control in an engine's style: a VNDF sampler
// whose basis is built with its cross product the wrong way round, so it
// draws the visible normals of the mirrored view (-ix, -iy, iz).  Its pdf is
// the VNDF's; the samples must fail both chi-square tests.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

GGX_INLINE ggx_vec3 ggx_user_sample_m(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_heitz(ggx_vec3_make(-i.x, -i.y, i.z), ax, ay, u1, u2).m;
}

GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return ggx_pdf_heitz(i, o, ax, ay);
}
