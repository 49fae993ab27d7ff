// ggx_fresnel.h - Fresnel reflectance and the roughness conventions of
// material models, as scalar device functions (OpenCL C, C++17 and CUDA:
// ggx_platform.h).  The renderer multiplies a BSDF value of ggx_bsdf.h by
// the Fresnel term of its material, per colour channel:
//   ggx_fresnel_dielectric(c, eta)     exact, unpolarized, relative index eta
//   ggx_fresnel_conductor(c, eta, k)   exact, complex index eta + i k (one channel)
//   ggx_fresnel_schlick(c, f0)         Schlick's approximation
// with c = i.m, the cosine between the view and the microfacet normal.
// Roughness: ggx_alpha_from_perceptual_roughness maps the artist's value to
// alpha; ggx_is_effectively_smooth says when to shade a surface as a mirror.
// docs/MATH.md "Fresnel and roughness" states the formulas.
#ifndef GGX_FRESNEL_H
#define GGX_FRESNEL_H

#include "ggx_platform.h"

// Dielectric interface, eta = index below the surface over index above.
// A cosine c < 0 (the view below) sees the interface from the other side,
// with index 1/eta.  With ct the refracted cosine (Snell's law),
//   F = (A^2 + B^2) / 2,  A = (c - eta ct) / (c + eta ct),  B = (eta c - ct) / (eta c + ct)
// on both sides (from below the two polarizations trade these forms), and
// total internal reflection (ct^2 <= 0) reflects everything (Walter et al.
// 2007, eq. 22).  ct^2 is written without forming 1/eta or 1 - sin^2, which
// cancel near the critical angle: above, ((eta - 1)(eta + 1) + c^2) / eta^2;
// below, (1 - eta)(1 + eta) + eta^2 c^2.
GGX_INLINE ggx_real ggx_fresnel_dielectric(ggx_real c, ggx_real eta)
{
    // Selects, not branches: a dielectric's lobe choice stays vectorizable on CPUs.
    const ggx_real d = (eta - GGX_R(1.0f)) * (eta + GGX_R(1.0f));
    const ggx_real a_c = ggx_fmin(ggx_fabs(c), GGX_R(1.0f));
    const ggx_real ct2 = c >= GGX_R(0.0f) ? (d + a_c * a_c) / (eta * eta) : eta * eta * a_c * a_c - d;
    const ggx_real ct = ggx_sqrt(ggx_fmax(ct2, GGX_R(0.0f)));
    const ggx_real a = (a_c - eta * ct) / (a_c + eta * ct);
    const ggx_real b = (eta * a_c - ct) / (eta * a_c + ct);
    return ct2 > GGX_R(0.0f) ? GGX_R(0.5f) * (a * a + b * b) : GGX_R(1.0f);
}

// Conductor of complex relative index eta + i k, at cosine c in [0, 1], for
// one wavelength (call once per channel).  The exact reflectance written in
// real arithmetic: with s2 = 1 - c^2, t0 = eta^2 - k^2 - s2 and a, b the
// real and imaginary parts of sqrt((eta + i k)^2 - s2), so that
// a^2 - b^2 = t0 and a^2 b^2 = eta^2 k^2,
//   Rs = ((a - c)^2 + b^2) / ((a + c)^2 + b^2),
//   Rp = Rs ((a c - s2)^2 + b^2 c^2) / ((a c + s2)^2 + b^2 c^2),
// F = (Rs + Rp) / 2.  k = 0 and eta > 1 give the dielectric value.
// Written against cancellation, which the critical angle of eta < 1 and
// normal incidence at eta near 1 expose: t0 = c^2 + (eta^2 - 1) - k^2 by
// fused multiply-adds (one rounding each, no 1 - c^2 formed); of a^2 and b^2
// the larger is (sqrt(t0^2 + 4 eta^2 k^2) + |t0|) / 2, a sum of positives,
// and the smaller eta^2 k^2 over it; and the numerators as sums of squares
// rather than differences of the expanded terms.
GGX_INLINE ggx_real ggx_fresnel_conductor(ggx_real c, ggx_real eta, ggx_real k)
{
    c = ggx_clamp(c, GGX_R(0.0f), GGX_R(1.0f));
    const ggx_real c2 = c * c, s2 = GGX_R(1.0f) - c2, ek = eta * k;
    const ggx_real t0 = ggx_fma(c, c, ggx_fma(-k, k, ggx_fma(eta, eta, -GGX_R(1.0f))));
    const ggx_real twice_larger = ggx_sqrt(t0 * t0 + GGX_R(4.0f) * ek * ek) + ggx_fabs(t0);
    const ggx_real larger = GGX_R(0.5f) * twice_larger;
    const ggx_real smaller = twice_larger > GGX_R(0.0f) ? GGX_R(2.0f) * ek * ek / twice_larger : GGX_R(0.0f);
    const ggx_real a2 = t0 >= GGX_R(0.0f) ? larger : smaller, b2 = t0 >= GGX_R(0.0f) ? smaller : larger;
    const ggx_real a = ggx_sqrt(a2);
    const ggx_real rs = ((a - c) * (a - c) + b2) / ((a + c) * (a + c) + b2);
    const ggx_real ac = a * c, b2c2 = b2 * c2;
    const ggx_real rp = rs * ((ac - s2) * (ac - s2) + b2c2) / ((ac + s2) * (ac + s2) + b2c2);
    return GGX_R(0.5f) * (rs + rp);
}

// Schlick 1994: F0 + (1 - F0) (1 - c)^5, F0 the reflectance at normal
// incidence; c clamped to [0, 1].
GGX_INLINE ggx_real ggx_fresnel_schlick(ggx_real c, ggx_real f0)
{
    const ggx_real x = GGX_R(1.0f) - ggx_clamp(c, GGX_R(0.0f), GGX_R(1.0f));
    const ggx_real x2 = x * x;
    return f0 + (GGX_R(1.0f) - f0) * (x2 * x2 * x);
}

// alpha = roughness^2: the perceptual roughness of Burley's model, glTF,
// Filament and Unreal.  (pbrt-v4's RoughnessToAlpha is another convention:
// alpha = sqrt(roughness).)
GGX_INLINE ggx_real ggx_alpha_from_perceptual_roughness(ggx_real roughness)
{
    return roughness * roughness;
}

// Below this alpha a renderer should shade a mirror (a delta lobe) rather
// than sample the microfacet lobe: 99% of the normals then lie within 0.01
// rad of the surface normal (docs/MATH.md; pbrt-v4's EffectivelySmooth uses
// the same bound).
#define GGX_SMOOTH_ALPHA GGX_R(1e-3f)

GGX_INLINE bool ggx_is_effectively_smooth(ggx_real ax, ggx_real ay)
{
    return ggx_fmax(ax, ay) < GGX_SMOOTH_ALPHA;
}

#endif
