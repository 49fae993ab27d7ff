// ggx_dielectric_side.hpp - which side of the interface a view is on, and the frame mirrored through
// the surface in which the dielectric functions see every view from above (internal helper; SPEC
// "Rough dielectrics": flip, use 1/eta, flip back), with the few surface quantities the dielectric
// needs in that frame: heights above the surface, t(w), D(m) and the even G2.
#pragma once

#include <cmath>

#include "ggx_reference.hpp"

namespace ggxref::detail {

struct Side {
    Method method;
    Vec3 n;       // unit surface normal: (0, 0, 1), or the normalized params.n for caps_iso
    bool below;   // the view has i.n < 0
    Params p;     // the caller's params with the view mirrored when below (n as given)
    double eta;   // the index seen from the view's side: eta, or 1/eta when below

    // x mirrored through the surface when the view is below (exactly z -> -z for n = z), else x: it
    // carries directions both ways between the caller's frame and the view-above frame.
    Vec3 flip(const Vec3& x) const { return below ? x - 2.0 * dot(x, n) * n : x; }
    double height(const Vec3& w) const { return dot(w, n); }
    double t(const Vec3& w) const { return method == Method::caps_iso ? t_iso(w, p.n, p.ax) : t_of(w, p.ax, p.ay); }
    double ndf(const Vec3& m) const { return method == Method::caps_iso ? D_iso(m, p.n, p.ax) : D(m, p.ax, p.ay); }
    // G2 = 1 / (1 + Lambda(i) + Lambda(o)) with Lambda even in o: the height-correlated form with
    // o mirrored to the view's side, 2 iz oz / (t(i) oz + t(o) iz).
    double g2_even(const Vec3& i, const Vec3& o) const
    {
        const double iz = height(i), oz = std::fabs(height(o));
        return iz > 0.0 && oz > 0.0 ? 2.0 * iz * oz / (t(i) * oz + t(o) * iz) : 0.0;
    }
};

// The unit normal a method reads: params.n for caps_iso, (0, 0, 1) otherwise.
inline Vec3 surface_normal(Method method, const Params& p)
{
    return method == Method::caps_iso ? normalize(p.n) : Vec3{0.0, 0.0, 1.0};
}

// i.n == 0 counts as above.
inline Side side_of(Method method, const Params& p, double eta)
{
    Side s{method, surface_normal(method, p), false, p, eta};
    s.below = dot(p.i, s.n) < 0.0;
    s.p.i = s.flip(p.i);
    s.eta = s.below ? 1.0 / eta : eta;
    return s;
}

inline bool eta_ok(double eta) { return eta > 0.0 && std::isfinite(eta) && eta != 1.0; }

}  // namespace ggxref::detail
