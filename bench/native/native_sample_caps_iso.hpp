// native_sample_caps_iso.hpp - method `caps-iso`: isotropic spherical-cap VNDF sampling in world
// space with no local basis (Benyoub 2024 blog).  Takes the world-space normal n and view i; the
// cap is drawn around +z and carried onto n by the half-turn about w = n + z:
// x -> (w.x) w / w.z - x, which maps z to n.  Singular at n = -z.
#pragma once

#include "native_sample_caps.hpp"

namespace ggxnative {

// The isotropic stretch about n: the tangential part of x scaled by alpha.
inline Vec3 stretch_about(Vec3 x, Vec3 n, float alpha) { return alpha * x + ((1.0f - alpha) * dot(x, n)) * n; }

// 1/(iz + t) about n, cancellation-free for iz < 0: (t - iz) / (alpha^2 |i_t|^2), with the
// tangential part i_t = i - iz n taken as a vector so a nearly normal i keeps its precision.
inline float inv_iz_plus_t_about(Vec3 i, Vec3 n, float alpha, float iz, float ti)
{
    if (iz >= 0.0f)
        return 1.0f / (iz + ti);
    Vec3 tangential = i - iz * n;
    return (ti - iz) / (alpha * alpha * dot(tangential, tangential));
}

inline Sample sample_caps_iso(Vec3 n, Vec3 i, float alpha, float u1, float u2)
{
    // Stretch the tangential part of i by alpha (blog: "warp to the hemisphere configuration").
    float iz = dot(i, n);
    Vec3 stretched_i = stretch_about(i, n, alpha);
    float ti = length(stretched_i);
    Vec3 v = (1.0f / ti) * stretched_i;
    // A cap around +z with the height of v above the surface, then the half-turn onto n.
    Vec3 c_std = sample_cap(iz / ti, u1, u2);
    Vec3 w = {n.x, n.y, n.z + 1.0f};
    Vec3 c = (dot(w, c_std) / w.z) * w - c_std;
    Vec3 h = c + v;  // standard-space half vector
    // Unstretch: m = normalize(alpha h_t + hz n); D(m) = |A h|^4 / (pi alpha^2 |h|^4).
    Vec3 a = stretch_about(h, n, alpha);
    float ratio = dot(a, a) / dot(h, h);
    float inv_sum = inv_iz_plus_t_about(i, n, alpha, iz, ti);
    Sample s;
    s.m = normalize(a);
    s.o = reflect(i, s.m);
    s.pdf_o = 0.5f * ratio * ratio / (pi * alpha * alpha) * inv_sum;
    s.pdf_m = 4.0f * std::fmax(0.0f, dot(i, s.m)) * s.pdf_o;  // the VNDF's max(0, i.m)
    float oz = dot(s.o, n);
    float g2 = G2_from_t(iz, oz, ti, length(stretch_about(s.o, n, alpha)));
    s.weight = iz > 0.0f ? g2 / (2.0f * iz * inv_sum) : 0.0f;
    return s;
}

}  // namespace ggxnative
