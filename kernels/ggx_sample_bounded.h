// ggx_sample_bounded.h - method `bounded`: the spherical cap of `caps` cut
// tighter so that fewer reflections land below the horizon (Eto & Tokuyoshi
// 2023, "Bounded VNDF Sampling for Smith-GGX Reflections", and supplement),
// with the bound carried to roughness a > 1 (docs/MATH.md "bounded").
#ifndef GGX_SAMPLE_BOUNDED_H
#define GGX_SAMPLE_BOUNDED_H

#include "ggx_sample_caps.h"

// a = min(ax, ay), the roughness the bound is taken for, kept below 1e18 so that a^2 stays
// finite (k has reached its limit -iz^2/w^2 to float precision long before).
GGX_INLINE ggx_real ggx_bounded_a(ggx_real ax, ggx_real ay)
{
    return ggx_fmin(ggx_fmin(ax, ay), GGX_R(1e18f));
}

// The bound k of the cap, with w = 1 + |(ix, iy)| (supplement eq. 1 bounded below over its
// azimuth; docs/MATH.md "bounded"): k = (1 - a^2) w^2 / (w^2 + a^2 iz^2) for a <= 1 (the paper's
// k, in [0, 1]) and k = (1 - a^2) iz^2 / (iz^2 + a^2 w^2) for a > 1 (in (-1, 0]: the cap stops
// above the stretched horizon); views below the horizon keep k = 1.
GGX_INLINE ggx_real ggx_bounded_k(ggx_vec3 i, ggx_real ax, ggx_real ay)
{
    ggx_real a = ggx_bounded_a(ax, ay), a2 = a * a;
    ggx_real w = GGX_R(1.0f) + ggx_sqrt(i.x * i.x + i.y * i.y);
    ggx_real w2 = w * w, iz2 = i.z * i.z;
    bool rough = a > GGX_R(1.0f);
    ggx_real p = rough ? iz2 : w2, q = rough ? w2 : iz2;  // scalar selects: both forms are (1 - a^2) p / (p + a^2 q)
    ggx_real k = (GGX_R(1.0f) - a2) * p / (p + a2 * q);
#if GGX_BELOW_HORIZON
    return i.z > GGX_R(0.0f) ? k : GGX_R(1.0f);
#else
    return k;  // iz = 0 gives k iz = 0 either way
#endif
}

// k iz + t(i) for iz >= 0, which is > 0. Plain for a <= 1 (k >= 0); for a > 1 (k < 0, and the plain
// sum cancels as a grows near the pole) the same sum of non-negative terms,
// (iz^2 (t + iz) + a^2 w (q w / (t + iz) + 2 iz |ih|)) / (iz^2 + a^2 w^2) with q = t^2 - iz^2,
// ih = (ix, iy) and w^2 - iz^2 = 2 |ih| w (a unit view).
GGX_INLINE ggx_real ggx_bounded_sum(ggx_vec3 i, ggx_real k, ggx_real ti, ggx_real ax, ggx_real ay)
{
    ggx_real a = ggx_bounded_a(ax, ay), a2 = a * a;
    ggx_real ih = ggx_sqrt(i.x * i.x + i.y * i.y), w = GGX_R(1.0f) + ih;
    ggx_real sx = ax * i.x, sy = ay * i.y, q = sx * sx + sy * sy;
    ggx_real tz = ti + i.z;
    ggx_real rough_sum = (i.z * i.z * tz + a2 * w * (q * w / tz + GGX_R(2.0f) * i.z * ih)) / (i.z * i.z + a2 * w * w);
    return a > GGX_R(1.0f) ? rough_sum : k * i.z + ti;
}

// 1/(k iz + t(i)): from ggx_bounded_sum for iz > 0, cancellation-free for iz < 0 (k = 1).
GGX_INLINE ggx_real ggx_bounded_inv_sum(ggx_vec3 i, ggx_real k, ggx_real ti, ggx_real ax, ggx_real ay)
{
    ggx_real inv = GGX_R(1.0f) / ggx_bounded_sum(i, k, ti, ax, ay);
#if GGX_BELOW_HORIZON
    return i.z > GGX_R(0.0f) ? inv : ggx_inv_iz_plus_t(i.z, ti, ax, ay, i);
#else
    return inv;
#endif
}

GGX_INLINE ggx_sample ggx_draw_bounded(ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1, ggx_real u2)
{
    ggx_real ti = ggx_t(i, ax, ay), inv_ti = GGX_R(1.0f) / ti;
    ggx_vec3 v = ggx_scale(ggx_stretch(i, ax, ay), inv_ti);
    ggx_real k = ggx_bounded_k(i, ax, ay);
    ggx_real lower = k * v.z;
    ggx_real inv_sum = ggx_bounded_inv_sum(i, k, ti, ax, ay);        // supplement sec. 2: D / (2 (k iz + t))
    bool below = GGX_BELOW_HORIZON != 0 && i.z < GGX_R(0.0f);  // false in builds that promise views above
    // The cap z in (-k vz, 1] (supplement sec. 2, q_our), of height 1 + k vz = (k iz + t) / t; below the
    // horizon k = 1 and the cap is caps' (ggx_cap_height).  It is thin below the horizon and for k < 0
    // (a > 1, lower = k vz < 0): 1 + k vz nears 0 as a grows at the pole.
#if GGX_BELOW_HORIZON
    ggx_real height = i.z > GGX_R(0.0f) ? ggx_bounded_sum(i, k, ti, ax, ay) * inv_ti
                                        : ggx_cap_height(lower, ti, inv_sum, below);
#else
    ggx_real height = ggx_bounded_sum(i, k, ti, ax, ay) * inv_ti;
#endif
    ggx_vec3 c = ggx_sample_cap_of_height(lower, height, u1, u2, lower < GGX_R(0.0f));
    ggx_vec3 h = ggx_cap_half_vector(c, v, height, u2, below);
    return ggx_finish_vndf_sample(i, h, ax, ay, ti, inv_sum);
}

// The bounded sample, or the fallback of ggx_guards.h (a roughness axis of
// 0, the view exactly opposite the normal).
GGX_INLINE ggx_sample ggx_sample_bounded(ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1, ggx_real u2)
{
    ggx_real key = ggx_bounded_inv_sum(i, ggx_bounded_k(i, ax, ay), ggx_t(i, ax, ay), ax, ay);
    return ggx_guard(ggx_draw_bounded(i, ax, ay, u1, u2), key, ax, ay);
}

// pdf of o from (i, o): D(m)/(2 (k iz + t)) inside the bounded cap, 0 outside.
// The stretched reflection o^ = 2 (v.m^) m^ - v must satisfy o^z >= -k vz
// (supplement, chi+ in sec. 2); a 1e-6 margin absorbs float rounding at the rim.
GGX_INLINE ggx_real ggx_pdf_bounded(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    ggx_real ti = ggx_t(i, ax, ay);
    ggx_vec3 v = ggx_scale(ggx_stretch(i, ax, ay), GGX_R(1.0f) / ti);
    ggx_real k = ggx_bounded_k(i, ax, ay);
    ggx_vec3 m = ggx_half_vector(i, o);
    ggx_vec3 m_std = ggx_normalize(ggx_vec3_make(m.x / ax, m.y / ay, m.z));
    ggx_real o_std_z = GGX_R(2.0f) * ggx_dot(v, m_std) * m_std.z - v.z;
    bool inside = o_std_z >= -k * v.z - GGX_R(1e-6f);
    ggx_real pdf = GGX_R(0.5f) * ggx_D(m, ax, ay) * ggx_bounded_inv_sum(i, k, ti, ax, ay);
    return ggx_guard_pdf(inside ? pdf : GGX_R(0.0f), ax, ay);
}

GGX_TANGENT_SPACE_DISPATCH(bounded)

#endif
