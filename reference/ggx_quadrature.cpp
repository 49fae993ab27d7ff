// ggx_quadrature.cpp - normalization, accepted mass, bounded-cap mass and directional albedo of
// the reference pdfs, integrated over standard-space normals (do = 4 |i.m| dw_m).
#include "ggx_quadrature.hpp"

#include <cmath>

#include "ggx_standard_space.hpp"

namespace ggxref {
namespace {

using detail::Local;

Local problem_of(Method method, const Params& p)
{
    return method == Method::caps_iso ? detail::isotropic_problem(p) : detail::tangent_problem(p);
}

void append(std::vector<double>& a, const std::vector<double>& b) { a.insert(a.end(), b.begin(), b.end()); }

// int pdf_o(o) do over the sphere (or over oz > 0), pulled back to normals: do = 4 |i.m| dw_m,
// with 4 |i.m| taken as 2 |i + o| of the rounded o, the value pdf_o itself sees (near o = -i the
// NDF-sampling pdf is ~ 1 / |i + o|, and the two must cancel).
double mass(Method method, const Params& p, bool upper_only)
{
    const Local L = problem_of(method, p);
    const double k = method == Method::bounded && p.i.z > 0.0 ? bounded_k(p.i, p.ax, p.ay) : 1.0;
    auto density = [&](const Vec3&, const Vec3& m) {
        const Vec3 o = reflect(p.i, L.outer(m));
        if (upper_only && dot(o, L.n) <= 0.0)
            return 0.0;
        return pdf_o(method, p, o) * 2.0 * length(p.i + o);
    };
    auto cuts = [&](double phi) {
        // NDF sampling is smooth across i.m = 0 (D mz dw_m); cutting there would only pull nodes
        // towards o = -i, where o carries rounding noise.
        std::vector<double> c;
        if (method != Method::ndf)
            c = detail::cuts_visible(L, phi);
        if (k < 1.0)
            append(c, detail::cuts_bounded_cap(L, phi, k));
        if (upper_only)
            append(c, detail::cuts_horizon(L, phi));
        return c;
    };
    return detail::integrate_standard(L, density, cuts);
}

}  // namespace

double integrate_pdf_o(Method method, const Params& p) { return mass(method, p, false); }
double integrate_pdf_o_upper(Method method, const Params& p) { return mass(method, p, true); }

// Caps pdf over the directions whose stretched reflection ohat = reflect(ih, ms) has
// ohat.z >= -k ih.z (Eto-Tokuyoshi cap; k = 1 below the horizon).
double bounded_cap_mass_of_caps(const Params& p)
{
    const Local L = detail::tangent_problem(p);
    const double k = p.i.z > 0.0 ? bounded_k(p.i, p.ax, p.ay) : 1.0;
    auto density = [&](const Vec3& ms, const Vec3& m) {
        if (reflect(L.ih, ms).z < -k * L.ih.z)
            return 0.0;
        return pdf_o(Method::caps, p, reflect(p.i, m)) * 4.0 * std::fabs(dot(p.i, m));
    };
    auto cuts = [&](double phi) {
        std::vector<double> c = detail::cuts_visible(L, phi);
        append(c, detail::cuts_bounded_cap(L, phi, k));
        return c;
    };
    return detail::integrate_standard(L, density, cuts);
}

// E(i) = int_{oz>0} D(h) G2hc(i,o) / (4 iz) do; G2 -> 0 at oz = 0, so the horizon is only a kink.
double albedo(const Params& p)
{
    const bool tangent = p.n.x == 0.0 && p.n.y == 0.0 && p.n.z == 1.0;
    const Local L = tangent ? detail::tangent_problem(p) : detail::isotropic_problem(p);
    auto density = [&](const Vec3&, const Vec3& m) {
        return brdf_cos(L.i, reflect(L.i, m), L.ax, L.ay) * 4.0 * std::fabs(dot(L.i, m));
    };
    auto cuts = [&](double phi) {
        std::vector<double> c = detail::cuts_visible(L, phi);
        append(c, detail::cuts_horizon(L, phi));
        return c;
    };
    return detail::integrate_standard(L, density, cuts);
}

}  // namespace ggxref
