// ggx_standard_space.hpp - integration over microfacet normals in the standard (stretched) space
// (internal helper of ggx_quadrature.cpp). With m = normalize(ax msx, ay msy, msz) the GGX NDF is
// the uniform hemisphere: D(m) mz dw_m = msz/pi dw_ms, smooth at any alpha, where dw_m = ax ay /
// |(ax msx, ay msy, msz)|^3 dw_ms. Integrals run over polar angles (th, phi) of ms, each meridian
// split where the integrand has a kink or a jump; these cuts have closed forms.
#pragma once

#include <algorithm>
#include <vector>

#include "ggx_adaptive.hpp"
#include "ggx_reference.hpp"

namespace ggxref::detail {

// The problem in tangent space; a tangent vector v is v.x e1 + v.y e2 + v.z n in the caller's frame.
struct Local {
    double ax, ay;
    Vec3 i;          // view, tangent space
    Vec3 ih;         // stretched view normalize(ax ix, ay iy, iz)
    Vec3 e1, e2, n;  // tangent frame in the caller's coordinates
    Vec3 outer(const Vec3& v) const { return v.x * e1 + v.y * e2 + v.z * n; }
};
Local tangent_problem(const Params&);    // identity frame
Local isotropic_problem(const Params&);  // frame about p.n, alpha = p.ax, as caps_iso sees it

// x in (lo, hi) with P sin x + Q cos x + C = 0.
std::vector<double> harmonic_roots(double P, double Q, double C, double lo, double hi);

// Polar angles th in (0, pi/2) on the meridian phi of ms = (sin th cos phi, sin th sin phi, cos th) where
std::vector<double> cuts_visible(const Local&, double phi);                // ih.ms = 0 (i.m = 0)
std::vector<double> cuts_bounded_cap(const Local&, double phi, double k);  // ohat.z = -k ih.z
std::vector<double> cuts_horizon(const Local&, double phi);                // oz = 0, o = reflect(i, m)

// density(ms, m) dw_m / (dth dphi) at ms = (sin th cos phi, sin th sin phi, cos th), c = cos phi,
// s = sin phi: dw_m = ax ay / |(ax msx, ay msy, msz)|^3 sin th dth dphi.
template <class Density>
double standard_integrand(const Local& L, const Density& density, double th, double c, double s)
{
    const double st = std::sin(th);
    const Vec3 ms{st * c, st * s, std::cos(th)};
    const Vec3 w{L.ax * ms.x, L.ay * ms.y, ms.z};
    const double len = length(w);
    return density(ms, (1.0 / len) * w) * L.ax * L.ay / (len * len * len) * st;
}

// The integral of f over th in (0, pi/2) on one meridian, as the sum of integrate(f, a, b) over the
// pieces between the kinks `cuts` (any order, any number inside or at the ends).
template <class F, class Integrate>
double integrate_meridian(const F& f, std::vector<double> cuts, const Integrate& integrate)
{
    constexpr double pi = 3.14159265358979323846;
    cuts.push_back(0.0);
    cuts.push_back(0.5 * pi);
    std::sort(cuts.begin(), cuts.end());
    double sum = 0.0;
    for (size_t k = 0; k + 1 < cuts.size(); ++k)
        if (cuts[k + 1] > cuts[k])
            sum += integrate(f, cuts[k], cuts[k + 1]);
    return sum;
}

// int over the hemisphere of ms of density(ms, m) dw_m; cuts(phi) lists the kinks of a meridian.
template <class Density, class Cuts> double integrate_standard(const Local& L, const Density& density, const Cuts& cuts)
{
    constexpr double pi = 3.14159265358979323846;
    const Tolerance inner{1e-14, 1e-12}, outer{1e-13, 1e-11};
    auto meridian = [&](double phi) {
        const double c = std::cos(phi), s = std::sin(phi);
        auto f = [&](double th) { return standard_integrand(L, density, th, c, s); };
        return integrate_meridian(f, cuts(phi), [&](const auto& g, double a, double b) {
            return adaptive_gauss(g, a, b, inner);
        });
    };
    // The visibility cut reaches the horizon where ih_xy is perpendicular to the meridian.
    const double phi0 = std::atan2(L.ih.y, L.ih.x) + 0.5 * pi;
    return adaptive_gauss(meridian, phi0, phi0 + pi, outer) +
           adaptive_gauss(meridian, phi0 + pi, phi0 + 2.0 * pi, outer);
}

}  // namespace ggxref::detail
