// native_sample_heitz.hpp - methods `heitz` (Heitz 2018, JCGT 7(4), the warped-disk form as
// refactored in Listing 2 of Dupuy & Benyoub 2023) and `heitz2017` (the half-disk form of the
// 2017 report, hal-01509746).  Both sample the visible hemisphere of the stretched view through
// a basis (T1, T2) around it.  They assume iz >= 0.
#pragma once

#include "native_ggx_math.hpp"

namespace ggxnative {

// Lifts the disk point (t1, t2) in the plane of (T1, T2) onto the unit hemisphere along v.
inline Vec3 lift_to_hemisphere(float t1, float t2, Vec3 T1, Vec3 T2, Vec3 v)
{
    float tv = std::sqrt(std::fmax(0.0f, 1.0f - t1 * t1 - t2 * t2));
    return t1 * T1 + t2 * T2 + tv * v;
}

// Unit vector (sx, sy, 0)/|(sx, sy)|, or (1, 0, 0) when the view is the pole.
inline Vec3 tangent_or_x(float sx, float sy)
{
    float len2 = sx * sx + sy * sy;
    if (!(len2 > 0.0f))
        return {1.0f, 0.0f, 0.0f};
    float inv = 1.0f / std::sqrt(len2);
    return {sx * inv, sy * inv, 0.0f};
}

inline Sample sample_heitz(Vec3 i, float ax, float ay, float u1, float u2)
{
    float ti = t_of(i, ax, ay);
    Vec3 v = (1.0f / ti) * stretch(i, ax, ay);  // stretched view (Heitz 2018, sec. 2)
    Vec3 T1 = tangent_or_x(-v.y, v.x);          // basis around v (Listing 2, l. 5-8)
    Vec3 T2 = cross(v, T1);
    float sin_phi, cos_phi;
    sincos_2pi(u2, sin_phi, cos_phi);
    float r = std::sqrt(u1);  // uniform point on the unit disk
    float t1 = r * cos_phi, t2 = r * sin_phi;
    float s = 0.5f * (1.0f + v.z);  // warp onto the visible cross section
    t2 = (1.0f - s) * std::sqrt(std::fmax(0.0f, 1.0f - t1 * t1)) + s * t2;
    Vec3 h = lift_to_hemisphere(t1, t2, T1, T2, v);
    h.z = std::fmax(0.0f, h.z);
    return finish_vndf_sample(i, h, ax, ay, ti, inv_iz_plus_t(i, ti, ax, ay));
}

inline Sample sample_heitz2017(Vec3 i, float ax, float ay, float u1, float u2)
{
    float ti = t_of(i, ax, ay);
    Vec3 v = (1.0f / ti) * stretch(i, ax, ay);  // stretch view (report sec. 1)
    Vec3 T1 = tangent_or_x(v.y, -v.x);          // T1 = normalize(V x z), eq. 1
    Vec3 T2 = cross(T1, v);                     // eq. 2
    // Choose a half disk by its projected area, a = 1/(1 + vz) (eq. 4), and scale the angle
    // within it: phi in [0, pi) or [pi, 2 pi).
    float a = 1.0f / (1.0f + v.z);
    bool first_half = u2 < a;
    float turn = first_half ? 0.5f * u2 / a : 0.5f + 0.5f * (u2 - a) / (1.0f - a);
    float sin_phi, cos_phi;
    sincos_2pi(turn, sin_phi, cos_phi);
    float r = std::sqrt(u1);  // eq. 3
    float p1 = r * cos_phi;
    float p2 = r * sin_phi * (first_half ? 1.0f : v.z);  // eq. 5: the tangent half disk is foreshortened
    Vec3 h = lift_to_hemisphere(p1, p2, T1, T2, v);     // eq. 6
    h.z = std::fmax(0.0f, h.z);
    return finish_vndf_sample(i, h, ax, ay, ti, inv_iz_plus_t(i, ti, ax, ay));
}

}  // namespace ggxnative
