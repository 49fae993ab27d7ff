// ggx_dielectric_integrals.cpp - the rough dielectric's integrals over microfacet normals: the
// probability of a valid sample and the single-scattering white furnace (reflectance and
// transmittance). Each o of a lobe has exactly one normal (the half vector or the generalized half
// vector facing up), so an integral over o is one over m with the lobe's Jacobian.
#include <cmath>
#include <limits>
#include <vector>

#include "ggx_dielectric.hpp"
#include "ggx_dielectric_normals.hpp"

namespace ggxref {
namespace {

using detail::Lobes;

std::vector<double> no_cuts(double) { return {}; }

bool roughness_ok(const Params& p)
{
    return p.ax > 0.0 && p.ay > 0.0 && std::isfinite(p.ax) && std::isfinite(p.ay);
}

}  // namespace

// int pdf_m(m) (F [o_r valid] + (1 - F) [o_t valid]) dw_m, with pdf_m = D(m) mz for NDF sampling
// and the VNDF D(m) max(0, i.m) / sigma(i) for the other methods (docs/MATH.md "Shared quantities").
double dielectric_valid_probability(Method method, const Params& p, double eta)
{
    if (method == Method::bounded || !detail::eta_ok(eta) || !roughness_ok(p))
        return 0.0;
    const detail::Side side = detail::side_of(method, p, eta);
    const detail::Local L = detail::dielectric_problem(side);
    auto density = [&](const Lobes& l, const Vec3& m) {
        const double pdf_m = method == Method::ndf ? D(m, L.ax, L.ay) * m.z : vndf_pdf(m, L.i, L.ax, L.ay);
        return pdf_m * ((l.reflects ? l.F : 0.0) + (l.transmits ? 1.0 - l.F : 0.0));
    };
    return detail::integrate_lobes(L, side.eta, density, no_cuts);
}

// Reflectance: int dielectric_cos(i, o_r) do_r with do_r = 4 (i.m) dw_m; transmittance: int
// dielectric_cos(i, o_t) do_t with do_t = (c - eta cos_t)^2 / (eta^2 cos_t) dw_m (SPEC Jacobian,
// inverted). dielectric_cos is called with the view from above and the index seen from there.
DielectricAlbedo dielectric_albedo(const Params& p, double eta, bool radiance)
{
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    if (!detail::eta_ok(eta) || !roughness_ok(p))
        return {nan, nan};
    const bool tangent = p.n.x == 0.0 && p.n.y == 0.0 && p.n.z == 1.0;
    const detail::Side side = detail::side_of(tangent ? Method::caps : Method::caps_iso, p, eta);
    const detail::Local L = detail::dielectric_problem(side);
    const double e = side.eta;
    auto reflected = [&](const Lobes& l, const Vec3&) {
        return l.reflects ? dielectric_cos(L.i, l.o_r, L.ax, L.ay, e, radiance) * 4.0 * l.c : 0.0;
    };
    auto transmitted = [&](const Lobes& l, const Vec3&) {
        if (!l.transmits)
            return 0.0;
        return dielectric_cos(L.i, l.o_t, L.ax, L.ay, e, radiance) * detail::refraction_spread(l, e);
    };
    return {detail::integrate_lobes(L, e, reflected, no_cuts), detail::integrate_lobes(L, e, transmitted, no_cuts)};
}

}  // namespace ggxref
