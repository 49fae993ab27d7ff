// native_sample_caps.hpp - method `caps`: visible normals as half vectors between the stretched
// view and a direction drawn uniformly from a spherical cap (Dupuy & Benyoub 2023, sec. 3).
// No basis, so no basis singularity.
#pragma once

#include <algorithm>

#include "native_ggx_math.hpp"

namespace ggxnative {

// A direction drawn uniformly from the spherical cap z in (-lower, 1] around +z of the given
// height 1 + lower: phi = 2 pi u1, z = (1 - u2) height - lower (Dupuy & Benyoub, Listing 3).
inline Vec3 sample_cap_of_height(float lower, float height, float u1, float u2)
{
    float z = (1.0f - u2) * height - lower;
    float sin_theta = std::sqrt(std::clamp(1.0f - z * z, 0.0f, 1.0f));
    float sin_phi, cos_phi;
    sincos_2pi(u1, sin_phi, cos_phi);
    return {sin_theta * cos_phi, sin_theta * sin_phi, z};
}

// The same with the height 1 + lower.
inline Vec3 sample_cap(float lower, float u1, float u2) { return sample_cap_of_height(lower, 1.0f + lower, u1, u2); }

inline Sample sample_caps(Vec3 i, float ax, float ay, float u1, float u2)
{
    float ti = t_of(i, ax, ay);
    Vec3 v = (1.0f / ti) * stretch(i, ax, ay);  // warp to the hemisphere configuration
    Vec3 c = sample_cap(v.z, u1, u2);           // reflected direction in that space (eq. 10)
    Vec3 h = c + v;                             // unnormalized half vector (sec. 3.3)
    return finish_vndf_sample(i, h, ax, ay, ti, inv_iz_plus_t(i, ti, ax, ay));
}

}  // namespace ggxnative
