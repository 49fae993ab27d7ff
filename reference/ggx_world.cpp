// ggx_world.cpp - the Duff et al. basis and world-space samples of the reference.
#include "ggx_world.hpp"

#include <cmath>

namespace ggxref {

Basis duff_basis(const Vec3& n)
{
    // Listing 3: s = sign(nz) (+1 for nz = +0), a = -1 / (s + nz), b = nx ny a.
    double s = std::copysign(1.0, n.z);
    double a = -1.0 / (s + n.z);
    double b = n.x * n.y * a;
    return {{1.0 + s * n.x * n.x * a, s * b, -s * n.x}, {b, s + n.y * n.y * a, -n.y}, n};
}

Vec3 to_local(const Basis& basis, const Vec3& v)
{
    return {dot(v, basis.t), dot(v, basis.b), dot(v, basis.n)};
}

Vec3 to_world(const Basis& basis, const Vec3& v)
{
    return v.x * basis.t + v.y * basis.b + v.z * basis.n;
}

Sample sample_world(Method method, const Params& params, double u1, double u2)
{
    if (method == Method::caps_iso)
        return sample(method, params, u1, u2);
    Basis basis = duff_basis(params.n);
    Params local = params;
    local.i = to_local(basis, params.i);
    local.n = {0.0, 0.0, 1.0};
    Sample s = sample(method, local, u1, u2);
    s.m = to_world(basis, s.m);
    s.o = to_world(basis, s.o);
    return s;
}

}  // namespace ggxref
