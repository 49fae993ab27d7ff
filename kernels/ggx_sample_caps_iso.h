// ggx_sample_caps_iso.h - method `caps-iso`: isotropic spherical-cap VNDF
// sampling in world space with no local basis (Benyoub 2024 blog).  It takes
// the world-space normal n and view i and returns m and o in world space.
// The cap is drawn around +z and carried onto n by the half-turn about
// w = n + z: x -> (w.x) w / w.z - x, which maps z to n.  Singular at n = -z.
#ifndef GGX_SAMPLE_CAPS_ISO_H
#define GGX_SAMPLE_CAPS_ISO_H

#include "ggx_sample_caps.h"

// Build option GGX_NORMAL_IS_Z=1 promises n = (0, 0, 1): the projections
// about n are then the tangent-space ones and the half-turn about w = 2z
// negates x and y, so caps-iso becomes caps with its cap turned by pi,
// without the per-sample work about a general n (which IEEE float math
// cannot fold away at compile time).
#ifndef GGX_NORMAL_IS_Z
#define GGX_NORMAL_IS_Z 0
#endif

// The isotropic stretch about n: the tangential part of x scaled by alpha.
GGX_INLINE ggx_vec3 ggx_stretch_about(ggx_vec3 x, ggx_vec3 n, ggx_real alpha)
{
    ggx_real xn = ggx_dot(x, n);
    return ggx_add(ggx_scale(x, alpha), ggx_scale(n, (GGX_R(1.0f) - alpha) * xn));
}

// |x_t|^2, the squared tangential part x - (x.n) n, taken as a vector so a
// nearly normal x keeps its relative precision.
GGX_INLINE ggx_real ggx_tangential2(ggx_vec3 x, ggx_vec3 n, ggx_real xn)
{
    ggx_vec3 t = ggx_add(x, ggx_scale(n, -xn));
    return ggx_dot(t, t);
}

// t(i) about n: |alpha i_t + iz n| with i_t the tangential part of i.
GGX_INLINE ggx_real ggx_t_about(ggx_vec3 i, ggx_vec3 n, ggx_real alpha)
{
    ggx_vec3 s = ggx_stretch_about(i, n, alpha);
    return ggx_sqrt(ggx_dot(s, s));
}

// 1/(iz + t) about n, cancellation-free for iz < 0 (as ggx_inv_iz_plus_t).
GGX_INLINE ggx_real ggx_inv_iz_plus_t_about(ggx_vec3 i, ggx_vec3 n, ggx_real alpha, ggx_real iz, ggx_real ti)
{
#if GGX_BELOW_HORIZON
    bool above = iz >= GGX_R(0.0f);  // one division, its operands selected (as ggx_inv_iz_plus_t)
    return (above ? GGX_R(1.0f) : ti - iz) / (above ? iz + ti : alpha * alpha * ggx_tangential2(i, n, iz));
#else
    return GGX_R(1.0f) / (iz + ti);
#endif
}

// caps-iso about n = +z (see GGX_NORMAL_IS_Z).
GGX_INLINE ggx_sample ggx_draw_caps_iso_z(ggx_vec3 i, ggx_real alpha, ggx_real u1, ggx_real u2)
{
    ggx_real ti = ggx_t(i, alpha, alpha);
    ggx_vec3 v = ggx_scale(ggx_stretch(i, alpha, alpha), GGX_R(1.0f) / ti);
    ggx_real inv_sum = ggx_inv_iz_plus_t(i.z, ti, alpha, alpha, i);
    bool below = GGX_BELOW_HORIZON != 0 && i.z < GGX_R(0.0f);  // false in builds that promise views above
    ggx_real height = ggx_cap_height(v.z, ti, inv_sum, below);
    ggx_vec3 c = ggx_sample_cap_of_height(v.z, height, u1, u2, below);
    // The half-turn about z, then c + v (ggx_cap_half_vector of the turned c).
    ggx_vec3 h = ggx_cap_half_vector(ggx_vec3_make(-c.x, -c.y, c.z), v, height, u2, below);
    return ggx_finish_vndf_sample(i, h, alpha, alpha, ti, inv_sum);
}

GGX_INLINE ggx_sample ggx_draw_caps_iso(ggx_vec3 n, ggx_vec3 i, ggx_real alpha, ggx_real u1, ggx_real u2)
{
    // Stretch the tangential part of i by alpha (blog: "warp to the hemisphere configuration").
    ggx_real iz = ggx_dot(i, n);
    ggx_real ti = ggx_t_about(i, n, alpha), inv_ti = GGX_R(1.0f) / ti;
    ggx_vec3 v = ggx_scale(ggx_stretch_about(i, n, alpha), inv_ti);
    // A cap around +z with the height of v above the surface, then the half-turn onto n.
    ggx_real inv_sum = ggx_inv_iz_plus_t_about(i, n, alpha, iz, ti);
    bool below = GGX_BELOW_HORIZON != 0 && iz < GGX_R(0.0f);  // false in builds that promise views above
    ggx_real height = ggx_cap_height(iz * inv_ti, ti, inv_sum, below);
    ggx_vec3 c_std = ggx_sample_cap_of_height(iz * inv_ti, height, u1, u2, below);
    ggx_vec3 w = ggx_vec3_make(n.x, n.y, n.z + GGX_R(1.0f));
    ggx_real inv_wz = GGX_R(1.0f) / w.z;  // a reciprocal, not a division per sample: w is uniform when n is
    ggx_vec3 c = ggx_add(ggx_scale(w, ggx_dot(w, c_std) * inv_wz), ggx_scale(c_std, -GGX_R(1.0f)));
    ggx_vec3 h = ggx_add(c, v);                                   // standard-space half vector
    // Unstretch: m = normalize(alpha h_t + hz n); D(m) = |A h|^4/(pi alpha^2 |h|^4).  (No floor on
    // h.n here, unlike ggx_vndf.h: about a general n, m.n at the cap's edge is 0 only to within
    // the rounding of world-space vectors anyway, and a vanishing h must stay NaN for the guard.)
    ggx_vec3 a = ggx_stretch_about(h, n, alpha);
#if GGX_BELOW_HORIZON
    // Below the horizon every component of c + v cancels along n: h is assembled from its part along
    // n, (1 - u2) height, and across it, the turned tangential part of c_std plus alpha i_t / t; A h
    // from the same parts (docs/MATH.md "Views near -n").
    ggx_vec3 c_flat = ggx_vec3_make(c_std.x, c_std.y, GGX_R(0.0f));
    ggx_vec3 c_t = ggx_add(ggx_scale(w, ggx_dot(w, c_flat) * inv_wz), ggx_scale(c_flat, -GGX_R(1.0f)));
    ggx_vec3 h_t = ggx_add(c_t, ggx_scale(ggx_add(i, ggx_scale(n, -iz)), alpha * inv_ti));
    ggx_vec3 h_n = ggx_scale(n, (GGX_R(1.0f) - u2) * height);
    ggx_real inv_height = GGX_R(1.0f) / height;  // as ggx_cap_half_vector: no component underflows at the rim
    ggx_vec3 h_below = ggx_scale(ggx_add(h_t, h_n), inv_height);
    ggx_vec3 a_below = ggx_scale(ggx_add(ggx_scale(h_t, alpha), h_n), inv_height);
    h = ggx_vec3_make(below ? h_below.x : h.x, below ? h_below.y : h.y, below ? h_below.z : h.z);
    a = ggx_vec3_make(below ? a_below.x : a.x, below ? a_below.y : a.y, below ? a_below.z : a.z);
#endif
    ggx_real ratio = ggx_dot(a, a) / ggx_dot(h, h);
    ggx_sample result;
    result.m = ggx_normalize(a);
    result.o = ggx_reflect(i, result.m);
    result.pdf_o = GGX_R(0.5f) * ratio * ratio / (GGX_PI * alpha * alpha) * inv_sum;
    // The VNDF's max(0, i.m), as ggx_vndf.h.
    result.pdf_m = GGX_R(4.0f) * ggx_fmax(GGX_R(0.0f), ggx_dot(i, result.m)) * result.pdf_o;
    ggx_real oz = ggx_dot(result.o, n);
    ggx_real g2 = ggx_G2_from_t(iz, oz, ti, ggx_t_about(result.o, n, alpha));
    result.weight = iz > GGX_R(0.0f) ? g2 / (GGX_R(2.0f) * iz * inv_sum) : GGX_R(0.0f);
    return result;
}

// The caps-iso sample, or the fallback of ggx_guards.h about n (alpha 0, the
// view exactly opposite n, and n = -z, where the half-turn about n + z is undefined).
GGX_INLINE ggx_sample ggx_sample_caps_iso(ggx_vec3 n, ggx_vec3 i, ggx_real alpha, ggx_real u1, ggx_real u2)
{
#if GGX_NORMAL_IS_Z
    ggx_real key = ggx_inv_iz_plus_t(i.z, ggx_t(i, alpha, alpha), alpha, alpha, i);
    return ggx_guard(ggx_draw_caps_iso_z(i, alpha, u1, u2), key, alpha, alpha);
#else
    ggx_real iz = ggx_dot(i, n), ti = ggx_t_about(i, n, alpha);
    ggx_sample s = ggx_draw_caps_iso(n, i, alpha, u1, u2);
    // key = (2 + m.z) / ((iz + t) (1 + nz)), between 1 and 3 times the reciprocal of the visible
    // area times 1 + nz.  The factor 2 + m.z: a view within rounding of -n about a tilted n makes
    // h = c + v vanish and m NaN, which the key carries to the guard; and the division after m
    // keeps LLVM's SLP vectorizer from pairing it with the reciprocal in normalize(), a pair
    // that stopped PoCL from vectorizing the work-items on 8-wide (AVX2) targets.
#if GGX_BELOW_HORIZON
    ggx_real key = (GGX_R(2.0f) + s.m.z) * ggx_inv_iz_plus_t_about(i, n, alpha, iz, ti) / (n.z + GGX_R(1.0f));
#else
    ggx_real key = (GGX_R(2.0f) + s.m.z) / ((iz + ti) * (n.z + GGX_R(1.0f)));
#endif
    return ggx_guard_about(s, key, n, alpha, alpha);
#endif
}

// pdf of o from (n, i, o): D(m)/(2 (iz + t)) with m the half vector, all about n
// (the blog's appendix writes the same as alpha^2 / (4 pi N^2 sigma)).
GGX_INLINE ggx_real ggx_pdf_caps_iso(ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, ggx_real alpha)
{
#if GGX_NORMAL_IS_Z
    return ggx_guard_pdf(ggx_pdf_vndf_reflection(i, o, alpha, alpha), alpha, alpha);
#endif
    ggx_vec3 m = ggx_half_vector(i, o);
    ggx_real mz = ggx_dot(m, n);
    ggx_real s = ggx_tangential2(m, n, mz) / (alpha * alpha) + mz * mz;
    ggx_real D = mz > GGX_R(0.0f) ? GGX_R(1.0f) / (GGX_PI * alpha * alpha * s * s) : GGX_R(0.0f);
    ggx_real iz = ggx_dot(i, n);
    return ggx_guard_pdf(GGX_R(0.5f) * D * ggx_inv_iz_plus_t_about(i, n, alpha, iz, ggx_t_about(i, n, alpha)), alpha,
                         alpha);
}

// The dispatchers' form (ggx_common.h): caps-iso reads n and the one roughness ax.
GGX_INLINE ggx_sample ggx_dispatch_sample_caps_iso(ggx_vec3 n, ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1,
                                                   ggx_real u2)
{
    GGX_UNUSED(ay);
    return ggx_sample_caps_iso(n, i, ax, u1, u2);
}

GGX_INLINE ggx_real ggx_dispatch_pdf_caps_iso(ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    GGX_UNUSED(ay);
    return ggx_pdf_caps_iso(n, i, o, ax);
}

#endif
