// ggx_vndf.h - pieces shared by the samplers of visible normals (heitz,
// heitz2017, caps, bounded): the stretch into the standard configuration
// where alpha = 1 (Heitz 2018, sec. 2), the unstretch of a normal, D(m)
// evaluated from the standard-space normal, and the estimator weight.
#ifndef GGX_VNDF_H
#define GGX_VNDF_H

#include "ggx_math.h"

// D(m) for m = normalize(ax h.x, ay h.y, h.z), h any non-zero standard-space
// normal: the NDF term becomes |A h|^4 / (pi ax ay |h|^4) with A = diag(ax, ay, 1).
GGX_INLINE ggx_real ggx_D_from_standard(ggx_vec3 h, ggx_real ax, ggx_real ay)
{
    ggx_vec3 a = ggx_stretch(h, ax, ay);
    ggx_real ratio = ggx_dot(a, a) / ggx_dot(h, h);
    return ratio * ratio / (GGX_PI * ax * ay);
}

// weight = D G2 / (4 iz) / pdf(o) = G2 (k iz + t(i)) / (2 iz), 0 when iz or oz <= 0.
GGX_INLINE ggx_real ggx_vndf_weight(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay, ggx_real ti, ggx_real inv_sum)
{
    ggx_real g2 = ggx_G2_from_t(i.z, o.z, ti, ggx_t(o, ax, ay));
    return i.z > GGX_R(0.0f) ? g2 / (GGX_R(2.0f) * i.z * inv_sum) : GGX_R(0.0f);
}

// The sample whose standard-space normal is h: m, o, densities and weight;
// ti = t(i) and inv_sum = 1 / (k iz + t(i)) with k = 1 for the plain VNDF.
// pdf(o) = D(m) / (2 (k iz + t)) (Dupuy & Benyoub 2023 eq. 20; Eto & Tokuyoshi supplement sec. 2),
// pdf(m) = pdf(o) 4 max(0, i.m), the max of the VNDF (Heitz 2018 eq. 1), as the m returned has it.
// i.m >= 0 in exact arithmetic, but where the cap point c nears -v, h = c + v cancels, the rounded
// m turns by ~6e-8 / |h| and i.m can come out below 0. (The exact i.m = t (v.h) / |A h| with
// v.h = |h|^2 / 2 is never negative, but it is that of the unrounded sample: on random uniforms it
// differs from the i.m of the m returned by up to 1e-2, relative; docs/MATH.md "i.m of a cap sample".)
GGX_INLINE ggx_sample ggx_finish_vndf_sample(ggx_vec3 i, ggx_vec3 h, ggx_real ax, ggx_real ay, ggx_real ti,
                                              ggx_real inv_sum)
{
    // Keep h above the horizon (pbrt-v4 floors at 1e-6; views below the horizon need all of
    // (0, 1e-6), so 1e-30): the last uniform, 1 - 2^-24, rounds onto the edge of the cap or
    // disk, where m would lie exactly in the surface.
    h.z = ggx_fmax(h.z, GGX_R(1e-30f));
    ggx_sample result;
    result.m = ggx_normalize(ggx_stretch(h, ax, ay));
    result.o = ggx_reflect(i, result.m);
    result.pdf_o = GGX_R(0.5f) * ggx_D_from_standard(h, ax, ay) * inv_sum;
    result.pdf_m = GGX_R(4.0f) * ggx_fmax(GGX_R(0.0f), ggx_dot(i, result.m)) * result.pdf_o;
    result.weight = ggx_vndf_weight(i, result.o, ax, ay, ti, inv_sum);
    return result;
}

// pdf of o recomputed from (i, o) for an unbounded VNDF sampler: m is the half vector.
GGX_INLINE ggx_real ggx_pdf_vndf_reflection(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    return ggx_vndf_reflection_pdf(ggx_half_vector(i, o), i, ax, ay);
}

#endif
