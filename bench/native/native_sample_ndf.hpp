// native_sample_ndf.hpp - method `ndf`: sampling D(m) mz (Walter et al. 2007, sec. 5.4).
// Reflections may land below the horizon; those samples are wasted (weight 0).
#pragma once

#include "native_ggx_math.hpp"

namespace ggxnative {

inline Sample sample_ndf(Vec3 i, float ax, float ay, float u1, float u2)
{
    // Walter eq. 35-36 in slope space: |slope|/alpha = r = sqrt(u1/(1-u1)), phi = 2 pi u2.
    float one_minus_u1 = 1.0f - u1;
    float r = std::sqrt(u1 / one_minus_u1);
    float sin_phi, cos_phi;
    sincos_2pi(u2, sin_phi, cos_phi);
    // The normal of slope (sx, sy) is (-sx, -sy, 1) normalized.
    Sample s;
    s.m = normalize({-ax * r * cos_phi, -ay * r * sin_phi, 1.0f});
    s.o = reflect(i, s.m);
    // D(m) = 1/(pi ax ay mz^4 (1 + r^2)^2) and 1 + r^2 = 1/(1 - u1), so
    // pdf(m) = D(m) mz = (1 - u1)^2 / (pi ax ay mz^3).
    float mz = s.m.z;
    s.pdf_m = one_minus_u1 * one_minus_u1 / (pi * ax * ay * mz * mz * mz);
    // Reflection Jacobian |dm/do| = 1/(4 |i.m|) (Walter eq. 14).
    float i_dot_m = dot(i, s.m);
    s.pdf_o = s.pdf_m / (4.0f * std::fabs(i_dot_m));
    // weight = D G2 / (4 iz) / pdf(o) = G2 (i.m) / (iz mz); a back-facing m reflects nothing.
    float g2 = G2_from_t(i.z, s.o.z, t_of(i, ax, ay), t_of(s.o, ax, ay));
    s.weight = (i_dot_m > 0.0f && i.z > 0.0f) ? g2 * i_dot_m / (i.z * mz) : 0.0f;
    return s;
}

}  // namespace ggxnative
