// ggx_bsdf.h - the value of the GGX BRDF for any pair of directions, for
// multiple importance sampling: a light sample's direction o needs f and
// the sampler's pdf of it, ggx_pdf_<method>(i, o) (ggx_samplers.h).
//   ggx_eval_reflection(i, o, ax, ay) -> f(i, o) |oz|, Fresnel 1
// The renderer multiplies by its Fresnel term F(i.h), h = ggx_half_vector(i, o)
// (ggx_fresnel.h), per colour channel.  The same height-correlated G2 as the
// samplers' weights, so for a sampled o: eval / pdf_o = weight.
#ifndef GGX_BSDF_H
#define GGX_BSDF_H

#include "ggx_math.h"

// f(i, o) oz = D(h) G2(i, o) / (4 iz) with h = (i + o)/|i + o| (Walter et
// al. 2007, eq. 20, times oz), for i and o above the surface (tangent space,
// n = z); 0 otherwise, as the samplers' weights are.  A two-sided material
// seen from below flips z of i and o before calling this and the pdf.
GGX_INLINE float ggx_eval_reflection(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    if (!(i.z > 0.0f && o.z > 0.0f))
        return 0.0f;
    const ggx_vec3 h = ggx_half_vector(i, o);
    return ggx_D(h, ax, ay) * ggx_G2(i, o, ax, ay) / (4.0f * i.z);
}

#endif
