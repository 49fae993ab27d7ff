// ggx_sample_bounded.h - method `bounded`: the spherical cap of `caps` cut
// tighter so that fewer reflections land below the horizon (Eto & Tokuyoshi
// 2023, "Bounded VNDF Sampling for Smith-GGX Reflections", and supplement).
#ifndef GGX_SAMPLE_BOUNDED_H
#define GGX_SAMPLE_BOUNDED_H

#include "ggx_sample_caps.h"

// The bound k of the cap: a = clamp(min(ax, ay), 0, 1), s = 1 + |(ix, iy)|,
// k = (1 - a^2) s^2 / (s^2 + a^2 iz^2); views below the horizon keep k = 1.
GGX_INLINE float ggx_bounded_k(ggx_vec3 i, float ax, float ay)
{
    float a = clamp(fmin(ax, ay), 0.0f, 1.0f);
    float a2 = a * a;
    float s = 1.0f + sqrt(i.x * i.x + i.y * i.y);
    float s2 = s * s;
    float k = (1.0f - a2) * s2 / (s2 + a2 * i.z * i.z);
#if GGX_BELOW_HORIZON
    return i.z > 0.0f ? k : 1.0f;
#else
    return k;  // iz = 0 gives k iz = 0 either way
#endif
}

// 1/(k iz + t(i)): plain for iz > 0 (k >= 0, t > 0), cancellation-free otherwise.
GGX_INLINE float ggx_bounded_inv_sum(ggx_vec3 i, float k, float ti, float ax, float ay)
{
#if GGX_BELOW_HORIZON
    return i.z > 0.0f ? 1.0f / (k * i.z + ti) : ggx_inv_iz_plus_t(i.z, ti, ax, ay, i);
#else
    return 1.0f / (k * i.z + ti);
#endif
}

GGX_INLINE ggx_sample ggx_draw_bounded(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    float ti = ggx_t(i, ax, ay);
    ggx_vec3 v = ggx_scale(ggx_stretch(i, ax, ay), 1.0f / ti);
    float k = ggx_bounded_k(i, ax, ay);
    ggx_vec3 c = ggx_sample_cap(k * v.z, u1, u2);                 // the cap z in (-k vz, 1]
    ggx_vec3 h = ggx_add(c, v);
    float inv_sum = ggx_bounded_inv_sum(i, k, ti, ax, ay);        // supplement sec. 2: D / (2 (k iz + t))
    return ggx_finish_vndf_sample(i, h, ax, ay, ti, inv_sum);
}

// The bounded sample, or the fallback of ggx_guards.h (a roughness axis of
// 0, the view exactly opposite the normal).
GGX_INLINE ggx_sample ggx_sample_bounded(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    float key = ggx_bounded_inv_sum(i, ggx_bounded_k(i, ax, ay), ggx_t(i, ax, ay), ax, ay);
    return ggx_guard(ggx_draw_bounded(i, ax, ay, u1, u2), key, ax, ay);
}

// pdf of o from (i, o): D(m)/(2 (k iz + t)) inside the bounded cap, 0 outside.
// The stretched reflection o^ = 2 (v.m^) m^ - v must satisfy o^z >= -k vz
// (supplement, chi+ in sec. 2); a 1e-6 margin absorbs float rounding at the rim.
GGX_INLINE float ggx_pdf_bounded(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    float ti = ggx_t(i, ax, ay);
    ggx_vec3 v = ggx_scale(ggx_stretch(i, ax, ay), 1.0f / ti);
    float k = ggx_bounded_k(i, ax, ay);
    ggx_vec3 m = ggx_half_vector(i, o);
    ggx_vec3 m_std = ggx_normalize(ggx_vec3_make(m.x / ax, m.y / ay, m.z));
    float o_std_z = 2.0f * ggx_dot(v, m_std) * m_std.z - v.z;
    int inside = o_std_z >= -k * v.z - 1e-6f;
    float pdf = 0.5f * ggx_D(m, ax, ay) * ggx_bounded_inv_sum(i, k, ti, ax, ay);
    return ggx_guard_pdf(inside ? pdf : 0.0f, ax, ay);
}

#endif
