// ggx_sample_caps.h - method `caps`: visible normals as half vectors between
// the stretched view and a direction drawn uniformly from a spherical cap
// (Dupuy & Benyoub 2023, sec. 3).  No basis, so no basis singularity.
#ifndef GGX_SAMPLE_CAPS_H
#define GGX_SAMPLE_CAPS_H

#include "ggx_guards.h"
#include "ggx_sincos.h"
#include "ggx_vndf.h"

// A direction drawn uniformly from the spherical cap z in (-lower, 1] around +z, whose
// height 1 + lower the caller gives (bounded has it without cancellation where lower nears -1):
// phi = 2 pi u1, z = (1 - u2) height - lower (Dupuy & Benyoub, Listing 3).
GGX_INLINE ggx_vec3 ggx_sample_cap_of_height(float lower, float height, float u1, float u2)
{
    float z = (1.0f - u2) * height - lower;
    float sin_theta = ggx_sqrt(ggx_clamp(1.0f - z * z, 0.0f, 1.0f));
    ggx_sin_cos phi = ggx_sincos_2pi(u1);
    float sin_phi = phi.sine, cos_phi = phi.cosine;
    return ggx_vec3_make(sin_theta * cos_phi, sin_theta * sin_phi, z);
}

// The same with the height 1 + lower.
GGX_INLINE ggx_vec3 ggx_sample_cap(float lower, float u1, float u2)
{
    return ggx_sample_cap_of_height(lower, 1.0f + lower, u1, u2);
}

GGX_INLINE ggx_sample ggx_draw_caps(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    float ti = ggx_t(i, ax, ay);
    ggx_vec3 v = ggx_scale(ggx_stretch(i, ax, ay), 1.0f / ti);   // warp to the hemisphere configuration
    ggx_vec3 c = ggx_sample_cap(v.z, u1, u2);                     // reflected direction in that space (eq. 10)
    ggx_vec3 h = ggx_add(c, v);                                   // unnormalized half vector (sec. 3.3)
    float inv_sum = ggx_inv_iz_plus_t(i.z, ti, ax, ay, i);
    return ggx_finish_vndf_sample(i, h, ax, ay, ti, inv_sum);
}

// The caps sample, or the fallback of ggx_guards.h (a roughness axis of 0,
// the view exactly opposite the normal).
GGX_INLINE ggx_sample ggx_sample_caps(ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_guard(ggx_draw_caps(i, ax, ay, u1, u2), ggx_inv_iz_plus_t(i.z, ggx_t(i, ax, ay), ax, ay, i), ax, ay);
}

GGX_INLINE float ggx_pdf_caps(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    return ggx_guard_pdf(ggx_pdf_vndf_reflection(i, o, ax, ay), ax, ay);
}

GGX_TANGENT_SPACE_DISPATCH(caps)

#endif
