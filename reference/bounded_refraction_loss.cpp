// bounded_refraction_loss.cpp - how much of a rough dielectric's transmission the bounded VNDF cap
// (Eto & Tokuyoshi 2023) cannot reach. The cap leaves out normals whose reflection would fall below
// the horizon; those normals still refract. The share is an integral over normals (VNDF times the
// refraction's probability 1 - F(i.m) times its weight G2 / G1(i)) over the normals outside the cap,
// divided by the same over all normals, in standard space with the cap's edge as a meridian cut.
#include <cmath>
#include <limits>

#include "ggx_dielectric.hpp"
#include "ggx_dielectric_normals.hpp"

namespace ggxref {

double bounded_lost_transmission(const Params& p, double eta)
{
    if (!detail::eta_ok(eta) || !(p.ax > 0.0 && p.ay > 0.0))
        return std::numeric_limits<double>::quiet_NaN();
    const detail::Side side = detail::side_of(Method::bounded, p, eta);
    const detail::Local L = detail::dielectric_problem(side);
    const double k = bounded_k(L.i, L.ax, L.ay);
    auto transmitted = [&](const detail::Lobes& l, const Vec3& m) {
        if (!l.transmits)
            return 0.0;
        return vndf_pdf(m, L.i, L.ax, L.ay) * (1.0 - l.F) * side.g2_even(L.i, l.o_t) / G1(L.i, L.ax, L.ay);
    };
    auto lost = [&](const detail::Lobes& l, const Vec3& m) {
        return pdf_m(Method::bounded, side.p, m) == 0.0 ? transmitted(l, m) : 0.0;
    };
    auto cap_edge = [&](double phi) { return detail::cuts_bounded_cap(L, phi, k); };
    const double all = detail::integrate_lobes(L, side.eta, transmitted, cap_edge);
    return detail::integrate_lobes(L, side.eta, lost, cap_edge) / all;
}

}  // namespace ggxref
