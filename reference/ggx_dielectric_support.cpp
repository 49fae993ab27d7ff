// ggx_dielectric_support.cpp - where a rough dielectric's density of o (and its BSDF) jumps or turns
// on the sphere of directions, for the integrals over o of ggx_bin_mass. With N the normal on the
// view's side and eta' the index seen from there, these edges are circles (Walter et al. 2007,
// eq. 40: i + eta' o_t = (i.m - eta' cos_t) m):
//   - the horizon o.N = 0: the reflection lobe on one side, the transmission lobe on the other;
//   - the image of the microfacet horizon m.N = 0, the latitude o.N = -(i.N) / eta': the
//     transmitted density jumps there (VNDF) or has a corner (D mz);
//   - the cone of refractions about -i, o.(-i) = min(eta', 1 / eta'): there i.m = 0 (eta' > 1) or
//     the refraction grazes the microfacet at the critical angle (eta' < 1), and 1 - F vanishes;
//   - for eta' < 1, the reflections at the critical angle, i.o = 1 - 2 eta'^2 (i.h^2 = (1 + i.o) / 2):
//     F reaches 1 there with a square-root corner.
// The narrow transmission lobe of an index near 1 (its width shrinks like |1 - 1/eta'| alpha) peaks
// near the smooth interface's refraction of i, taken as the support's point, where the quadrature
// refines; without a refraction (total internal reflection about N) the point is -i, where NDF
// sampling's reflection density grows like 1 / |i + o| for a view on the horizon.
#include "ggx_dielectric_support.hpp"

#include <cmath>

#include "ggx_dielectric_side.hpp"

namespace ggxref::detail {
namespace {

void add_circle(Support& s, const Vec3& axis, double height)
{
    if (std::fabs(height) < 1.0 - 1e-12)
        s.edges.emplace_back(circle(axis, height));
}

}  // namespace

Support dielectric_support(Method method, const Params& p, double eta)
{
    const Side side = side_of(method, p, eta);
    const Vec3 N = side.below ? -side.n : side.n;
    const Vec3& i = p.i;
    const double e = side.eta, iN = dot(i, N);
    Support s;
    add_circle(s, N, 0.0);
    add_circle(s, N, -iN / e);
    add_circle(s, -i, std::fmin(e, 1.0 / e));
    if (e < 1.0)
        add_circle(s, i, 1.0 - 2.0 * e * e);
    const double cos2_t = 1.0 - (1.0 - iN * iN) / (e * e);
    if (cos2_t > 0.0)
        set_point(s, (-1.0 / e) * i + (iN / e - std::sqrt(cos2_t)) * N);
    else
        set_point(s, -i);
    return s;
}

}  // namespace ggxref::detail
