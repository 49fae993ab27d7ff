// ndf_alpha_epsilon.h - a negative control in an engine's style: an exact NDF
// sampler whose pdf writes the NDF's numerator as alpha^2 + 1e-5 (a guard
// against alpha 0), so the pdf integrates to 1 + 1e-5 / alpha^2.  The
// integral must fail at alpha 0.05 (1.004) and 0.01 (1.1).
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_NDF

GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_ndf(i, ax, ay, u1, u2);
}

// D(h) h.z / (4 |i.h|), the isotropic D with alpha = ax.
GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    GGX_UNUSED(ay);
    ggx_vec3 h = ggx_normalize(ggx_add(i, o));
    h = h.z < 0.0f ? ggx_scale(h, -1.0f) : h;
    const float a2 = ax * ax;
    const float d = h.z * h.z * (a2 - 1.0f) + 1.0f;
    const float D = (a2 + 1e-5f) / (GGX_PI * d * d);
    return D * h.z / (4.0f * ggx_fabs(ggx_dot(i, h)));
}
