// native_basis.hpp - the orthonormal basis (b1, b2, n) around a unit normal n, branchless, from
// Duff et al. 2017, "Building an Orthonormal Basis, Revisited" (JCGT 6(1), Listing 3), and the
// change of coordinates between world space and the tangent space where n = (0, 0, 1).
#pragma once

#include "native_vec.hpp"

namespace ggxnative {

struct Basis {
    Vec3 b1, b2, n;  // right-handed: b1 x b2 = n

    Vec3 to_local(Vec3 w) const { return {dot(w, b1), dot(w, b2), dot(w, n)}; }
    Vec3 to_world(Vec3 w) const { return w.x * b1 + w.y * b2 + w.z * n; }
};

inline Basis make_basis(Vec3 n)
{
    float sign = std::copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    Basis basis;
    basis.b1 = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
    basis.b2 = {b, sign + n.y * n.y * a, -n.y};
    basis.n = n;
    return basis;
}

}  // namespace ggxnative
