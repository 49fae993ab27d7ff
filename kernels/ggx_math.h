// ggx_math.h - the GGX (Trowbridge-Reitz) microfacet model in tangent space,
// where the surface normal is (0, 0, 1): the normal distribution D, Smith's
// Lambda, masking G1, masking-shadowing G2 (height-correlated and separable),
// the projected area sigma and the VNDF and reflection densities.
// Anisotropic forms take (ax, ay); the `_iso` forms take one alpha.
// Notation: t(w) = |(ax wx, ay wy, wz)|, see docs/MATH.md "Shared quantities".
#ifndef GGX_MATH_H
#define GGX_MATH_H

#include "ggx_common.h"

// Build option GGX_BELOW_HORIZON: 1 (default) supports views below the
// horizon (iz < 0); 0 promises iz >= 0 and drops the forms that need it.
#ifndef GGX_BELOW_HORIZON
#define GGX_BELOW_HORIZON 1
#endif

GGX_INLINE ggx_real ggx_t(ggx_vec3 w, ggx_real ax, ggx_real ay)
{
    ggx_vec3 s = ggx_stretch(w, ax, ay);
    return ggx_sqrt(ggx_dot(s, s));
}

// D(m) = 1 / (pi ax ay (mx^2/ax^2 + my^2/ay^2 + mz^2)^2) for mz > 0 (Walter 2007, eq. 33).
GGX_INLINE ggx_real ggx_D(ggx_vec3 m, ggx_real ax, ggx_real ay)
{
    ggx_real qx = m.x / ax, qy = m.y / ay;
    ggx_real s = qx * qx + qy * qy + m.z * m.z;
    return m.z > GGX_R(0.0f) ? GGX_R(1.0f) / (GGX_PI * ax * ay * s * s) : GGX_R(0.0f);
}

GGX_INLINE ggx_real ggx_D_iso(ggx_vec3 m, ggx_real alpha)
{
    ggx_real a2 = alpha * alpha;
    ggx_real s = (m.x * m.x + m.y * m.y) / a2 + m.z * m.z;
    return m.z > GGX_R(0.0f) ? GGX_R(1.0f) / (GGX_PI * a2 * s * s) : GGX_R(0.0f);
}

// Smith Lambda(w) = (t(w)/|wz| - 1)/2 for wz > 0, and Lambda(-w) = 1 + Lambda(w).
GGX_INLINE ggx_real ggx_lambda(ggx_vec3 w, ggx_real ax, ggx_real ay)
{
    ggx_real half_ratio = GGX_R(0.5f) * ggx_t(w, ax, ay) / ggx_fabs(w.z);
    return w.z > GGX_R(0.0f) ? half_ratio - GGX_R(0.5f) : half_ratio + GGX_R(0.5f);
}

// G1(w) = 1/(1 + Lambda(w)) = 2 wz / (wz + t(w)) for wz > 0, else 0.
GGX_INLINE ggx_real ggx_G1(ggx_vec3 w, ggx_real ax, ggx_real ay)
{
    return w.z > GGX_R(0.0f) ? GGX_R(2.0f) * w.z / (w.z + ggx_t(w, ax, ay)) : GGX_R(0.0f);
}

// Height-correlated G2 = 1/(1 + Lambda(i) + Lambda(o)) written without
// divisions by iz or oz: 2 iz oz / (t(i) oz + t(o) iz) (Heitz 2014, eq. 99).
// Takes t(i) and t(o) so callers that have them pay no square root.  The
// denominator fused (GGX_FMA): written as a sum of two products it is a
// reduction that LLVM's SLP vectorizer pairs t(i) with t(o) for, and a
// 2-wide vector inside PoCL's work-item loop keeps that loop scalar.
GGX_INLINE ggx_real ggx_G2_from_t(ggx_real iz, ggx_real oz, ggx_real ti, ggx_real to)
{
    return (iz > GGX_R(0.0f) && oz > GGX_R(0.0f)) ? GGX_R(2.0f) * iz * oz / GGX_FMA(ti, oz, to * iz) : GGX_R(0.0f);
}

GGX_INLINE ggx_real ggx_G2(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    return ggx_G2_from_t(i.z, o.z, ggx_t(i, ax, ay), ggx_t(o, ax, ay));
}

// The separable form G1(i) G1(o).
GGX_INLINE ggx_real ggx_G2_separable(ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    return ggx_G1(i, ax, ay) * ggx_G1(o, ax, ay);
}

// 1 / (iz + t(i)) without the cancellation of iz + t for iz < 0:
// (t - iz) / (ax^2 ix^2 + ay^2 iy^2) (Eto & Tokuyoshi 2023 supplement, sec. 3).
// Built with GGX_BELOW_HORIZON=0 (the caller promises iz >= 0) only the plain form is computed.
GGX_INLINE ggx_real ggx_inv_iz_plus_t(ggx_real iz, ggx_real t, ggx_real ax, ggx_real ay, ggx_vec3 i)
{
#if GGX_BELOW_HORIZON
    ggx_real sx = ax * i.x, sy = ay * i.y;
    bool above = iz >= GGX_R(0.0f);  // one division, its operands selected: each side's quotient unchanged
    return (above ? GGX_R(1.0f) : t - iz) / (above ? iz + t : sx * sx + sy * sy);
#else
    return GGX_R(1.0f) / (iz + t);
#endif
}

// Projected area of the microsurface seen from i: sigma(i) = (iz + t(i))/2.
GGX_INLINE ggx_real ggx_projected_area(ggx_vec3 i, ggx_real ax, ggx_real ay)
{
    return GGX_R(0.5f) / ggx_inv_iz_plus_t(i.z, ggx_t(i, ax, ay), ax, ay, i);
}

// VNDF Dv(m; i) = max(0, i.m) D(m) / sigma(i) (Heitz 2018, eq. 1).
GGX_INLINE ggx_real ggx_vndf_pdf(ggx_vec3 m, ggx_vec3 i, ggx_real ax, ggx_real ay)
{
    ggx_real inv = ggx_inv_iz_plus_t(i.z, ggx_t(i, ax, ay), ax, ay, i);
    return GGX_R(2.0f) * ggx_fmax(GGX_R(0.0f), ggx_dot(i, m)) * ggx_D(m, ax, ay) * inv;
}

// Density of the reflection o of i about a VNDF-sampled m:
// Dv(m; i) / (4 i.m) = D(m) / (2 (iz + t(i))).
GGX_INLINE ggx_real ggx_vndf_reflection_pdf(ggx_vec3 m, ggx_vec3 i, ggx_real ax, ggx_real ay)
{
    ggx_real inv = ggx_inv_iz_plus_t(i.z, ggx_t(i, ax, ay), ax, ay, i);
    return GGX_R(0.5f) * ggx_D(m, ax, ay) * inv;
}

// Half vector of i and o, or (0, 0, 0) when o = -i (no microfacet reflects i into o).
GGX_INLINE ggx_vec3 ggx_half_vector(ggx_vec3 i, ggx_vec3 o)
{
    ggx_vec3 h = ggx_add(i, o);
    ggx_real len2 = ggx_dot(h, h);
    // A scalar select: struct selects do not vectorize.
    ggx_real scale = len2 > GGX_R(0.0f) ? ggx_rsqrt(len2) : GGX_R(0.0f);
    return ggx_scale(h, scale);
}

#endif
