// ggx_world.hpp - world-space sampling in the reference: the orthonormal basis
// of Duff et al. 2017 around a world normal, and each method's sample for a
// world-space normal and view (the tangent-space methods go through that basis;
// caps_iso samples in world space directly).
#pragma once

#include "ggx_reference.hpp"

namespace ggxref {

struct Basis {
    Vec3 t, b, n;  // right-handed: t x b = n
};

// Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin 2017, "Building an
// Orthonormal Basis, Revisited", JCGT 6(1), Listing 3 (branchless, valid at n = -z).
Basis duff_basis(const Vec3& n);
Vec3 to_local(const Basis& basis, const Vec3& v);
Vec3 to_world(const Basis& basis, const Vec3& v);

// Sample of `method` for the world-space unit normal params.n and view params.i
// (isotropic: params.ax); m and o in world space.
Sample sample_world(Method method, const Params& params, double u1, double u2);

}  // namespace ggxref
