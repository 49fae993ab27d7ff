// native_sample_bounded.hpp - method `bounded`: the spherical cap of `caps` cut tighter so that
// fewer reflections land below the horizon (Eto & Tokuyoshi 2023, "Bounded VNDF Sampling for
// Smith-GGX Reflections", and its supplement).
#pragma once

#include "native_sample_caps.hpp"

namespace ggxnative {

// The bound k of the cap: a = clamp(min(ax, ay), 0, 1), s = 1 + |(ix, iy)|,
// k = (1 - a^2) s^2 / (s^2 + a^2 iz^2); views below the horizon keep k = 1.
inline float bounded_k(Vec3 i, float ax, float ay)
{
    if (!(i.z > 0.0f))
        return 1.0f;
    float a = std::clamp(std::fmin(ax, ay), 0.0f, 1.0f);
    float a2 = a * a;
    float s = 1.0f + std::sqrt(i.x * i.x + i.y * i.y);
    float s2 = s * s;
    return (1.0f - a2) * s2 / (s2 + a2 * i.z * i.z);
}

inline Sample sample_bounded(Vec3 i, float ax, float ay, float u1, float u2)
{
    float ti = t_of(i, ax, ay);
    Vec3 v = (1.0f / ti) * stretch(i, ax, ay);
    float k = bounded_k(i, ax, ay);
    Vec3 c = sample_cap(k * v.z, u1, u2);  // the cap z in (-k vz, 1]
    Vec3 h = c + v;
    // Supplement sec. 2: pdf(o) = D / (2 (k iz + t)); below the horizon k = 1.
    float inv_sum = i.z > 0.0f ? 1.0f / (k * i.z + ti) : inv_iz_plus_t(i, ti, ax, ay);
    return finish_vndf_sample(i, h, ax, ay, ti, inv_sum);
}

}  // namespace ggxnative
