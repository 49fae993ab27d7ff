// ggx_bsdf.h - the value of the GGX BRDF for any pair of directions, for
// multiple importance sampling: a light sample's direction o needs f and
// the sampler's pdf of it, ggx_pdf_<method>(i, o) (ggx_samplers.h).
//   ggx_eval_reflection(i, o, ax, ay)                      -> f(i, o) |oz|, Fresnel 1
//   ggx_eval_transmission(i, o, ax, ay, eta, radiance)     -> the BTDF's f |oz|, Fresnel 0
//   ggx_eval_dielectric(i, o, ax, ay, eta, radiance)       -> both lobes with the exact Fresnel
// The renderer multiplies the first by its Fresnel term F(i.h), h =
// ggx_half_vector(i, o), and the second by 1 - F(i.m), m =
// ggx_transmission_half_vector(i, o, eta) (ggx_fresnel.h), per colour
// channel.  The same height-correlated G2 as the samplers' weights, so for a
// sampled o: eval / pdf_o = weight.  eta: index below the surface over index
// above; radiance = 1 for radiance transport (the BTDF divided by eta^2 as
// light enters the denser side), 0 for importance.
#ifndef GGX_BSDF_H
#define GGX_BSDF_H

#include "ggx_fresnel.h"
#include "ggx_math.h"

// f(i, o) oz = D(h) G2(i, o) / (4 iz) with h = (i + o)/|i + o| (Walter et
// al. 2007, eq. 20, times oz), for i and o above the surface (tangent space,
// n = z); 0 otherwise, as the samplers' weights are.  A two-sided material
// seen from below flips z of i and o before calling this and the pdf.
GGX_INLINE ggx_real ggx_eval_reflection(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    if (!(i.z > GGX_R(0.0f) && o.z > GGX_R(0.0f)))
        return GGX_R(0.0f);
    const ggx_vec3 h = ggx_half_vector(i, o);
    return ggx_D(h, ax, ay) * ggx_G2(i, o, ax, ay) / (GGX_R(4.0f) * i.z);
}

// The microfacet normal that refracts i into o across an interface of
// relative index eta: normalize(-(i + eta o)), turned to face up (for eta < 1
// -(i + eta o) points down).  (0, 0, 0) where i + eta o vanishes.
GGX_INLINE ggx_vec3 ggx_transmission_half_vector(ggx_vec3 i, ggx_vec3 o, ggx_real eta)
{
    ggx_vec3 h = ggx_add(i, ggx_scale(o, eta));
    const ggx_real len2 = ggx_dot(h, h);
    const ggx_real scale = len2 > GGX_R(0.0f) ? -ggx_rsqrt(len2) : GGX_R(0.0f);
    return ggx_scale(h, h.z > GGX_R(0.0f) ? -scale : scale);
}

// The BTDF times |oz| (Walter et al. 2007, eq. 21), for i above and o below
// the surface; a view below sees the interface from the other side (z of
// both flipped, index 1/eta).  With m = ggx_transmission_half_vector and
// G2 = 1 / (1 + Lambda(i) + Lambda(o)) with Lambda even in o (as pbrt-v4):
//   f |oz| = D(m) G2 |i.m| |o.m| eta^2 / (|iz| (i.m + eta o.m)^2)   (importance),
// divided by eta^2 for radiance.  0 unless i.m > 0 and o.m < 0 (SPEC: back-facing
// microfacets transmit nothing), or when i and o lie on one side.
GGX_INLINE ggx_real ggx_eval_transmission(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay, ggx_real eta, int radiance)
{
    if (!(i.z * o.z < GGX_R(0.0f)))
        return GGX_R(0.0f);
    if (i.z < GGX_R(0.0f)) {
        i.z = -i.z;
        o.z = -o.z;
        eta = GGX_R(1.0f) / eta;
    }
    const ggx_vec3 m = ggx_transmission_half_vector(i, o, eta);
    const ggx_real im = ggx_dot(i, m), om = ggx_dot(o, m);
    if (!(im > GGX_R(0.0f) && om < GGX_R(0.0f)))
        return GGX_R(0.0f);
    const ggx_vec3 o_up = ggx_vec3_make(o.x, o.y, -o.z);  // Lambda(o) = Lambda(o_up): the even form
    const ggx_real denominator = im + eta * om;
    const ggx_real value = ggx_D(m, ax, ay) * ggx_G2(i, o_up, ax, ay) * im * -om / (i.z * denominator * denominator);
    return radiance != 0 ? value : value * eta * eta;
}

// A rough dielectric's f |oz| with its Fresnel: F(i.h) times the reflection
// for o on the view's side, (1 - F(i.m)) times the transmission across; a
// view below sees the interface from the other side (z flipped, 1/eta).
GGX_INLINE ggx_real ggx_eval_dielectric(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay, ggx_real eta, int radiance)
{
    if (i.z < GGX_R(0.0f)) {
        i.z = -i.z;
        o.z = -o.z;
        eta = GGX_R(1.0f) / eta;
    }
    if (o.z > GGX_R(0.0f))
        return ggx_fresnel_dielectric(ggx_dot(i, ggx_half_vector(i, o)), eta) * ggx_eval_reflection(i, o, ax, ay);
    const ggx_real c = ggx_dot(i, ggx_transmission_half_vector(i, o, eta));
    return (GGX_R(1.0f) - ggx_fresnel_dielectric(c, eta)) * ggx_eval_transmission(i, o, ax, ay, eta, radiance);
}

#endif
