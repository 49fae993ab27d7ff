// native_sample_bounded.hpp - method `bounded`: the spherical cap of `caps` cut tighter so that
// fewer reflections land below the horizon (Eto & Tokuyoshi 2023, "Bounded VNDF Sampling for
// Smith-GGX Reflections", and its supplement), with the bound carried to roughness a > 1
// (docs/MATH.md "bounded").
#pragma once

#include "native_sample_caps.hpp"

namespace ggxnative {

// a = min(ax, ay), kept below 1e18 so that a^2 stays finite (k has reached its limit there).
inline float bounded_a(float ax, float ay) { return std::fmin(std::fmin(ax, ay), 1e18f); }

// The bound k of the cap, w = 1 + |(ix, iy)| (supplement eq. 1 bounded below over its azimuth;
// docs/MATH.md "bounded"): k = (1 - a^2) w^2 / (w^2 + a^2 iz^2) for a <= 1 (the paper's k) and
// k = (1 - a^2) iz^2 / (iz^2 + a^2 w^2) for a > 1 (k < 0); views below the horizon keep k = 1.
inline float bounded_k(Vec3 i, float ax, float ay)
{
    if (!(i.z > 0.0f))
        return 1.0f;
    float a = bounded_a(ax, ay), a2 = a * a;
    float w = 1.0f + std::sqrt(i.x * i.x + i.y * i.y);
    float w2 = w * w, iz2 = i.z * i.z;
    if (a > 1.0f)
        return (1.0f - a2) * iz2 / (iz2 + a2 * w2);
    return (1.0f - a2) * w2 / (w2 + a2 * iz2);
}

// k iz + t(i) for iz > 0: plain for a <= 1 (k >= 0); for a > 1 the same sum of non-negative terms,
// (iz^2 (t + iz) + a^2 w (q w / (t + iz) + 2 iz |ih|)) / (iz^2 + a^2 w^2), q = t^2 - iz^2, which
// does not cancel as a grows near the pole.
inline float bounded_sum(Vec3 i, float k, float ti, float ax, float ay)
{
    float a = bounded_a(ax, ay);
    if (!(a > 1.0f))
        return k * i.z + ti;
    float a2 = a * a;
    float ih = std::sqrt(i.x * i.x + i.y * i.y), w = 1.0f + ih;
    float sx = ax * i.x, sy = ay * i.y, q = sx * sx + sy * sy;
    float tz = ti + i.z;
    return (i.z * i.z * tz + a2 * w * (q * w / tz + 2.0f * i.z * ih)) / (i.z * i.z + a2 * w * w);
}

inline Sample sample_bounded(Vec3 i, float ax, float ay, float u1, float u2)
{
    float ti = t_of(i, ax, ay), inv_ti = 1.0f / ti;
    Vec3 v = inv_ti * stretch(i, ax, ay);
    float k = bounded_k(i, ax, ay);
    float lower = k * v.z;
    if (!(i.z > 0.0f)) {  // below the horizon k = 1: the caps sampler
        Vec3 c = sample_cap(lower, u1, u2);
        return finish_vndf_sample(i, c + v, ax, ay, ti, inv_iz_plus_t(i, ti, ax, ay));
    }
    // The cap z in (-k vz, 1] (supplement sec. 2), of height 1 + k vz = (k iz + t) / t, and
    // pdf(o) = D / (2 (k iz + t)).
    float sum = bounded_sum(i, k, ti, ax, ay);
    Vec3 c = sample_cap_of_height(lower, sum * inv_ti, u1, u2);
    return finish_vndf_sample(i, c + v, ax, ay, ti, 1.0f / sum);
}

}  // namespace ggxnative
