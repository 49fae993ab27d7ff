// ggx_sample_ndf.h - method `ndf`: sampling the normal distribution D(m) mz
// (Walter et al. 2007, sec. 5.4; seed blog part 1) and its reflection pdf.
#ifndef GGX_SAMPLE_NDF_H
#define GGX_SAMPLE_NDF_H

#include "ggx_guards.h"
#include "ggx_math.h"
#include "ggx_sincos.h"

GGX_INLINE ggx_sample ggx_draw_ndf(ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1, ggx_real u2)
{
    ggx_sample result;
    // Walter eq. 35-36 in slope space: |slope|/alpha = r = ggx_sqrt(u1/(1-u1)), phi = 2 pi u2.
    ggx_real one_minus_u1 = GGX_R(1.0f) - u1;
    ggx_real r = ggx_sqrt(u1 / one_minus_u1);
    ggx_sin_cos phi = ggx_sincos_2pi(u2);
    ggx_real sin_phi = phi.sine, cos_phi = phi.cosine;
    // The normal of slope (sx, sy) is (-sx, -sy, 1) normalized.
    result.m = ggx_normalize(ggx_vec3_make(-ax * r * cos_phi, -ay * r * sin_phi, GGX_R(1.0f)));
    result.o = ggx_reflect(i, result.m);
    // D(m) = 1/(pi ax ay mz^4 (1 + r^2)^2) and 1 + r^2 = 1/(1 - u1), so
    // pdf(m) = D(m) mz = (1 - u1)^2 / (pi ax ay mz^3).
    ggx_real mz = result.m.z;
    result.pdf_m = one_minus_u1 * one_minus_u1 / (GGX_PI * ax * ay * mz * mz * mz);
    // Reflection Jacobian |dm/do| = 1/(4 |o.m|) = 1/(4 |i.m|) (Walter eq. 14).
    ggx_real i_dot_m = ggx_dot(i, result.m);
    // (i.m = 0: a view across the surface reflected about m = n, o = -i has no density.)
    result.pdf_o = i_dot_m != GGX_R(0.0f) ? result.pdf_m / (GGX_R(4.0f) * ggx_fabs(i_dot_m)) : GGX_R(0.0f);
    // weight = D G2 / (4 iz) / pdf_o = G2 (i.m) / (iz mz); a back-facing m reflects nothing.
    ggx_real g2 = ggx_G2(i, result.o, ax, ay);
    result.weight = (i_dot_m > GGX_R(0.0f) && i.z > GGX_R(0.0f)) ? g2 * i_dot_m / (i.z * mz) : GGX_R(0.0f);
    return result;
}

// The ndf sample, or the fallback of ggx_guards.h (a roughness axis of 0).
GGX_INLINE ggx_sample ggx_sample_ndf(ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1, ggx_real u2)
{
    return ggx_guard(ggx_draw_ndf(i, ax, ay, u1, u2), GGX_R(1.0f), ax, ay);
}

// pdf of o recomputed from (i, o): the sampled m is the half vector flipped
// into the upper hemisphere (m and -m reflect i into the same o).
GGX_INLINE ggx_real ggx_pdf_ndf(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    ggx_vec3 h = ggx_half_vector(i, o);
    ggx_vec3 m = ggx_scale(h, h.z < GGX_R(0.0f) ? -GGX_R(1.0f) : GGX_R(1.0f));
    ggx_real i_dot_m = ggx_fabs(ggx_dot(i, m));
    ggx_real pdf = i_dot_m > GGX_R(0.0f) ? ggx_D(m, ax, ay) * m.z / (GGX_R(4.0f) * i_dot_m) : GGX_R(0.0f);
    return ggx_guard_pdf(pdf, ax, ay);
}

GGX_TANGENT_SPACE_DISPATCH(ndf)

#endif
