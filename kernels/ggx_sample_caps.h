// ggx_sample_caps.h - method `caps`: visible normals as half vectors between
// the stretched view and a direction drawn uniformly from a spherical cap
// (Dupuy & Benyoub 2023, sec. 3).  No basis, so no basis singularity.
#ifndef GGX_SAMPLE_CAPS_H
#define GGX_SAMPLE_CAPS_H

#include "ggx_guards.h"
#include "ggx_sincos.h"
#include "ggx_vndf.h"

// A direction drawn uniformly from the spherical cap z in (-lower, 1] around +z, whose
// height 1 + lower the caller gives (ggx_cap_height: without cancellation where lower nears -1):
// phi = 2 pi u1, z = (1 - u2) height - lower (Dupuy & Benyoub, Listing 3).  On a cap less than a
// hemisphere (`thin`: lower < 0, as below the horizon and for bounded's k < 0; the caller says so,
// false where it cannot be) the sine comes from 1 - z = u2 height, exactly (height = 1 + lower):
// sin^2 = u2 height (2 - u2 height), where 1 - z^2 cancels as the cap thins (docs/MATH.md "Views
// near -n").
GGX_INLINE ggx_vec3 ggx_sample_cap_of_height(ggx_real lower, ggx_real height, ggx_real u1, ggx_real u2, bool thin)
{
    ggx_real z = (GGX_R(1.0f) - u2) * height - lower;
    ggx_real sin2 = GGX_R(1.0f) - z * z;
    ggx_real depth = u2 * height;
    sin2 = thin ? depth * (GGX_R(2.0f) - depth) : sin2;
    ggx_real sin_theta = ggx_sqrt(ggx_clamp(sin2, GGX_R(0.0f), GGX_R(1.0f)));
    ggx_sin_cos phi = ggx_sincos_2pi(u1);
    ggx_real sin_phi = phi.sine, cos_phi = phi.cosine;
    return ggx_vec3_make(sin_theta * cos_phi, sin_theta * sin_phi, z);
}

// The height 1 + vz of the cap under the stretched view v = A i / t: below the horizon, where the sum
// cancels, 1 / (t (iz + t)^-1) with inv_sum = (iz + t)^-1 from ggx_inv_iz_plus_t (1 + vz = (iz + t) / t).
GGX_INLINE ggx_real ggx_cap_height(ggx_real vz, ggx_real ti, ggx_real inv_sum, bool below)
{
    ggx_real height = GGX_R(1.0f) + vz;
#if GGX_BELOW_HORIZON
    height = below ? GGX_R(1.0f) / (ti * inv_sum) : height;
#endif
    return height;
}

// The standard-space half vector h = c + v of a cap point c (eq. 10, sec. 3.3).  Below the horizon its
// z, c.z + vz, is (1 - u2) height exactly, where the sum cancels; and h is divided by the height (m and D
// do not see its length), so that a cap as thin as the guard lets through (height ~ 1e-20) leaves no
// component to underflow at its rim, where c + v cancels across too.
GGX_INLINE ggx_vec3 ggx_cap_half_vector(ggx_vec3 c, ggx_vec3 v, ggx_real height, ggx_real u2, bool below)
{
    ggx_vec3 h = ggx_add(c, v);
#if GGX_BELOW_HORIZON
    ggx_real inv_height = GGX_R(1.0f) / height;
    h = ggx_vec3_make(below ? h.x * inv_height : h.x, below ? h.y * inv_height : h.y, below ? GGX_R(1.0f) - u2 : h.z);
#endif
    return h;
}

GGX_INLINE ggx_sample ggx_draw_caps(ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1, ggx_real u2)
{
    ggx_real ti = ggx_t(i, ax, ay);
    ggx_vec3 v = ggx_scale(ggx_stretch(i, ax, ay), GGX_R(1.0f) / ti);   // warp to the hemisphere configuration
    ggx_real inv_sum = ggx_inv_iz_plus_t(i.z, ti, ax, ay, i);
    bool below = GGX_BELOW_HORIZON != 0 && i.z < GGX_R(0.0f);  // false in builds that promise views above
    ggx_real height = ggx_cap_height(v.z, ti, inv_sum, below);
    ggx_vec3 c = ggx_sample_cap_of_height(v.z, height, u1, u2, below);  // reflected direction in that space (eq. 10)
    ggx_vec3 h = ggx_cap_half_vector(c, v, height, u2, below);          // unnormalized half vector (sec. 3.3)
    return ggx_finish_vndf_sample(i, h, ax, ay, ti, inv_sum);
}

// The caps sample, or the fallback of ggx_guards.h (a roughness axis of 0,
// the view exactly opposite the normal).
GGX_INLINE ggx_sample ggx_sample_caps(ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1, ggx_real u2)
{
    return ggx_guard(ggx_draw_caps(i, ax, ay, u1, u2), ggx_inv_iz_plus_t(i.z, ggx_t(i, ax, ay), ax, ay, i), ax, ay);
}

GGX_INLINE ggx_real ggx_pdf_caps(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    return ggx_guard_pdf(ggx_pdf_vndf_reflection(i, o, ax, ay), ax, ay);
}

GGX_TANGENT_SPACE_DISPATCH(caps)

#endif
