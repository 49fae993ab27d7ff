// ggx_sample_heitz.h - methods `heitz` (Heitz 2018, JCGT 7(4): the warped
// disk form, as refactored in Listing 2 of Dupuy & Benyoub 2023) and
// `heitz2017` (the half-disk form of the 2017 report, hal-01509746).
// Both sample the visible part of the unit hemisphere seen from the
// stretched view, through a basis (T1, T2) around it.
#ifndef GGX_SAMPLE_HEITZ_H
#define GGX_SAMPLE_HEITZ_H

#include "ggx_guards.h"
#include "ggx_sincos.h"
#include "ggx_vndf.h"

// The point t1 T1 + t2 T2 + tv v of the unit hemisphere above the disk point (t1, t2) in the plane of
// (T1, T2), tv its height along v.
GGX_INLINE ggx_vec3 ggx_lift_by(ggx_real t1, ggx_real t2, ggx_real tv, ggx_vec3 T1, ggx_vec3 T2, ggx_vec3 v)
{
    return ggx_vec3_make(t1 * T1.x + t2 * T2.x + tv * v.x,
                         t1 * T1.y + t2 * T2.y + tv * v.y,
                         t1 * T1.z + t2 * T2.z + tv * v.z);
}

// Lifts the disk point (t1, t2) in the plane of (T1, T2) onto the unit hemisphere along v.
GGX_INLINE ggx_vec3 ggx_lift_to_hemisphere(ggx_real t1, ggx_real t2, ggx_vec3 T1, ggx_vec3 T2, ggx_vec3 v)
{
    return ggx_lift_by(t1, t2, ggx_sqrt(ggx_fmax(GGX_R(0.0f), GGX_R(1.0f) - t1 * t1 - t2 * t2)), T1, T2, v);
}

// Unit vector (sx, sy, 0)/|(sx, sy)|, or (1, 0, 0) when the view is the pole.
GGX_INLINE ggx_vec3 ggx_tangent_or_x(ggx_real sx, ggx_real sy)
{
    ggx_real len2 = sx * sx + sy * sy;
    ggx_real inv = ggx_rsqrt(len2);
    bool pole = !(len2 > GGX_R(0.0f));  // per-component selects: a select of structs does not vectorize
    return ggx_vec3_make(pole ? GGX_R(1.0f) : sx * inv, pole ? GGX_R(0.0f) : sy * inv, GGX_R(0.0f));
}

GGX_INLINE ggx_sample ggx_draw_heitz(ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1, ggx_real u2)
{
    ggx_real ti = ggx_t(i, ax, ay);
    ggx_vec3 v = ggx_scale(ggx_stretch(i, ax, ay), GGX_R(1.0f) / ti);   // stretched view (Heitz 2018, sec. 2)
    ggx_vec3 T1 = ggx_tangent_or_x(-v.y, v.x);                    // basis around v (Listing 2, l. 5-8)
    ggx_vec3 T2 = ggx_cross(v, T1);
    ggx_sin_cos phi = ggx_sincos_2pi(u2);
    ggx_real sin_phi = phi.sine, cos_phi = phi.cosine;
    ggx_real r = ggx_sqrt(u1);                                          // uniform point on the unit disk
    ggx_real t1 = r * cos_phi, t2 = r * sin_phi;
    ggx_real inv_sum = ggx_inv_iz_plus_t(i.z, ti, ax, ay, i);
    bool below = i.z < GGX_R(0.0f);
    ggx_real s = GGX_R(0.5f) * (GGX_R(1.0f) + v.z);                               // warp onto the visible cross section
#if GGX_BELOW_HORIZON
    s = below ? GGX_R(0.5f) / (ti * inv_sum) : s;                       // 1 + vz = (iz + t) / t without cancellation
#endif
    ggx_real w = ggx_sqrt(ggx_fmax(GGX_R(0.0f), GGX_R(1.0f) - t1 * t1));
    ggx_real t2w = (GGX_R(1.0f) - s) * w + s * t2;
    ggx_real tv2 = GGX_R(1.0f) - t1 * t1 - t2w * t2w;
#if GGX_BELOW_HORIZON
    // Below the horizon tv^2 = w^2 - t2w^2 and h.z = t2w |vxy| + tv vz cancel; exactly, with w - t2w =
    // s (w - t2) and t2w - |vz| w = s (w + t2) (|vz| = 1 - 2 s): tv^2 = s (w - t2)(w + t2w) and
    // h.z = s (w + t2)(t2w + |vz| w) / (t2w |vxy| + tv |vz|) (docs/MATH.md "Views near -n").
    tv2 = below ? s * (w - t2) * (w + t2w) : tv2;
#endif
    ggx_real tv = ggx_sqrt(ggx_fmax(GGX_R(0.0f), tv2));
    ggx_vec3 h = ggx_lift_by(t1, t2w, tv, T1, T2, v);
#if GGX_BELOW_HORIZON
    // (|vxy| is T2.z; den is 0 only where w = t2 = 0, the numerator too: the floor keeps 0 / 0 away.)
    ggx_real den = ggx_fmax(t2w * T2.z - tv * v.z, GGX_R(1e-30f));
    h.z = below ? s * (w + t2) * (t2w - v.z * w) / den : h.z;
#endif
    h.z = ggx_fmax(GGX_R(0.0f), h.z);
    return ggx_finish_vndf_sample(i, h, ax, ay, ti, inv_sum);
}

GGX_INLINE ggx_sample ggx_draw_heitz2017(ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1, ggx_real u2)
{
    ggx_real ti = ggx_t(i, ax, ay);
    ggx_vec3 v = ggx_scale(ggx_stretch(i, ax, ay), GGX_R(1.0f) / ti);   // stretch view (report sec. 1)
    ggx_vec3 T1 = ggx_tangent_or_x(v.y, -v.x);                    // T1 = normalize(V x z), eq. 1
    ggx_vec3 T2 = ggx_cross(T1, v);                               // eq. 2
    // Choose a half disk by its projected area, a = 1/(1 + vz) (eq. 4), and
    // scale the angle within it: phi in [0, pi) or [pi, 2 pi).
    ggx_real a = GGX_R(1.0f) / (GGX_R(1.0f) + v.z);
    bool first_half = u2 < a;
    ggx_real turn = first_half ? GGX_R(0.5f) * u2 / a : GGX_R(0.5f) + GGX_R(0.5f) * (u2 - a) / (GGX_R(1.0f) - a);
    ggx_sin_cos phi = ggx_sincos_2pi(turn);
    ggx_real sin_phi = phi.sine, cos_phi = phi.cosine;
    ggx_real r = ggx_sqrt(u1);                                          // eq. 3
    ggx_real p1 = r * cos_phi;
    ggx_real p2 = r * sin_phi * (first_half ? GGX_R(1.0f) : v.z);  // eq. 5: the tangent half disk is foreshortened
    ggx_vec3 h = ggx_lift_to_hemisphere(p1, p2, T1, T2, v);      // eq. 6
    h.z = ggx_fmax(GGX_R(0.0f), h.z);
    ggx_real inv_sum = ggx_inv_iz_plus_t(i.z, ti, ax, ay, i);
    return ggx_finish_vndf_sample(i, h, ax, ay, ti, inv_sum);
}

// The samples, or the fallback of ggx_guards.h (a roughness axis of 0, the
// view exactly opposite the normal).
GGX_INLINE ggx_sample ggx_sample_heitz(ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1, ggx_real u2)
{
    return ggx_guard(ggx_draw_heitz(i, ax, ay, u1, u2), ggx_inv_iz_plus_t(i.z, ggx_t(i, ax, ay), ax, ay, i), ax, ay);
}

GGX_INLINE ggx_sample ggx_sample_heitz2017(ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1, ggx_real u2)
{
    return ggx_guard(ggx_draw_heitz2017(i, ax, ay, u1, u2), ggx_inv_iz_plus_t(i.z, ggx_t(i, ax, ay), ax, ay, i), ax,
                     ay);
}

GGX_INLINE ggx_real ggx_pdf_heitz(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    return ggx_guard_pdf(ggx_pdf_vndf_reflection(i, o, ax, ay), ax, ay);
}

GGX_INLINE ggx_real ggx_pdf_heitz2017(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    return ggx_guard_pdf(ggx_pdf_vndf_reflection(i, o, ax, ay), ax, ay);
}

GGX_TANGENT_SPACE_DISPATCH(heitz)
GGX_TANGENT_SPACE_DISPATCH(heitz2017)

#endif
