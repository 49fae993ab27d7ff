// native_ggx_math.hpp - the GGX quantities the samplers share, in tangent space (n = (0, 0, 1)):
// t(w), masking-shadowing G2, 1/(iz + t), D from a standard-space normal, and the assembly of a
// VNDF-family sample with its densities and white-furnace weight (docs/MATH.md "Shared quantities").
#pragma once

#include <cmath>

#include "native_vec.hpp"

namespace ggxnative {

constexpr float pi = 3.14159265358979323846f;
constexpr float two_pi = 6.28318530717958647692f;

// What every sampler returns: microfacet normal m, reflected direction o, their densities per
// steradian, and the furnace weight f(i,o) oz / pdf(o) with Fresnel 1 (0 when wasted).
struct Sample {
    Vec3 m, o;
    float pdf_m, pdf_o, weight;
};

// sin and cos of the sampling angle 2 pi u.
inline void sincos_2pi(float u, float& s, float& c)
{
    float phi = two_pi * u;
    s = std::sin(phi);
    c = std::cos(phi);
}

// t(w) = |(ax wx, ay wy, wz)|.
inline float t_of(Vec3 w, float ax, float ay) { return length(stretch(w, ax, ay)); }

// Height-correlated G2 = 1/(1 + Lambda(i) + Lambda(o)) = 2 iz oz / (t(i) oz + t(o) iz)
// (Heitz 2014, eq. 99), 0 unless iz, oz > 0.
inline float G2_from_t(float iz, float oz, float ti, float to)
{
    if (!(iz > 0.0f && oz > 0.0f))
        return 0.0f;
    return 2.0f * iz * oz / (ti * oz + to * iz);
}

// 1/(iz + t(i)), cancellation-free for iz < 0: (t - iz) / (ax^2 ix^2 + ay^2 iy^2)
// (Eto & Tokuyoshi 2023 supplement, sec. 3).
inline float inv_iz_plus_t(Vec3 i, float ti, float ax, float ay)
{
    if (i.z >= 0.0f)
        return 1.0f / (i.z + ti);
    float sx = ax * i.x, sy = ay * i.y;
    return (ti - i.z) / (sx * sx + sy * sy);
}

// D(m) for m = normalize(ax h.x, ay h.y, h.z), h a non-zero standard-space normal:
// |A h|^4 / (pi ax ay |h|^4) with A = diag(ax, ay, 1).
inline float D_from_standard(Vec3 h, float ax, float ay)
{
    Vec3 a = stretch(h, ax, ay);
    float ratio = dot(a, a) / dot(h, h);
    return ratio * ratio / (pi * ax * ay);
}

// The sample whose standard-space normal is h; ti = t(i), inv_sum = 1/(k iz + t(i)) (k = 1 for the
// plain VNDF).  pdf(o) = D(m) / (2 (k iz + t)) (Dupuy & Benyoub 2023 eq. 20; Eto & Tokuyoshi
// supplement sec. 2), pdf(m) = 4 max(0, i.m) pdf(o), weight = G2 (k iz + t) / (2 iz).
inline Sample finish_vndf_sample(Vec3 i, Vec3 h, float ax, float ay, float ti, float inv_sum)
{
    Sample s;
    s.m = normalize(stretch(h, ax, ay));
    s.o = reflect(i, s.m);
    s.pdf_o = 0.5f * D_from_standard(h, ax, ay) * inv_sum;
    s.pdf_m = 4.0f * std::fmax(0.0f, dot(i, s.m)) * s.pdf_o;  // the VNDF's max(0, i.m) (kernels/ggx_vndf.h)
    float g2 = G2_from_t(i.z, s.o.z, ti, t_of(s.o, ax, ay));
    s.weight = i.z > 0.0f ? g2 / (2.0f * i.z * inv_sum) : 0.0f;
    return s;
}

}  // namespace ggxnative
