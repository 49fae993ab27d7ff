// ggx_dielectric_normals.hpp - integrals over microfacet normals for the rough dielectric (internal
// helper). A normal m of a view from above reflects i into o_r and refracts it into o_t (Walter et al.
// 2007, eqs. 39-40); the integration runs over standard-space normals (ggx_standard_space.hpp), each
// meridian cut where a lobe starts or stops: i.m = 0, o_r on the horizon, the critical angle
// (i.m = sqrt(1 - eta^2), eta < 1) and o_t on the horizon (possible for eta < 1 only).
#pragma once

#include <vector>

#include "ggx_dielectric_side.hpp"
#include "ggx_standard_space.hpp"

namespace ggxref::detail {

// The two lobes of the unit normal m (mz > 0) for the view i (iz >= 0), local frame n = z.
struct Lobes {
    double c;        // i.m
    double F;        // Fresnel reflectance at c (1 for c <= 0)
    double cos_t;    // -o_t.m; 0 at and past the critical angle
    Vec3 o_r, o_t;   // reflected and refracted directions
    bool reflects;   // c > 0 and o_r.z > 0
    bool transmits;  // c > 0, cos_t > 0 and o_t.z < 0
};
Lobes lobes_of(const Vec3& i, const Vec3& m, double eta);

// |d w_o / d w_m| of the refraction: (c - eta cos_t)^2 / (eta^2 cos_t), written as
// (1 - eta^2)^2 / (eta^2 cos_t (c + eta cos_t)^2) (Snell: c^2 - eta^2 cos_t^2 = 1 - eta^2).
double refraction_spread(const Lobes&, double eta);

// The view-above problem in its local frame: tangent, or isotropic about n for caps_iso.
Local dielectric_problem(const Side&);

// Polar angles in (0, pi/2) on the meridian phi where a lobe starts or stops (see above).
std::vector<double> dielectric_cuts(const Local&, double eta, double phi);

// Azimuths (mod pi) where a meridian touches the critical angle's or the refracted horizon's curve,
// so that the integral of a meridian has a square-root corner there.
std::vector<double> dielectric_turning_azimuths(const Local&, double eta);

// int over the normals of density(lobes, m) dw_m (m local), cut as above and at `extra(phi)`. Each
// piece, of a meridian or of the azimuth (split as in integrate_standard and where the meridians touch
// a curve), is integrated after the smoothstep map, whose flat ends smooth the square-root behaviour
// of 1 - F at the critical angle and of the meridians' integral where they touch a curve.
template <class Density, class Extra>
double integrate_lobes(const Local& L, double eta, const Density& density, const Extra& extra)
{
    constexpr double pi = 3.14159265358979323846;
    const Tolerance inner{1e-14, 1e-11}, outer{1e-13, 1e-10};
    auto over_ms = [&](const Vec3&, const Vec3& m) { return density(lobes_of(L.i, m, eta), m); };
    auto meridian = [&](double phi) {
        const double c = std::cos(phi), s = std::sin(phi);
        auto f = [&](double th) { return standard_integrand(L, over_ms, th, c, s); };
        std::vector<double> b = dielectric_cuts(L, eta, phi), e = extra(phi);
        b.insert(b.end(), e.begin(), e.end());
        return integrate_meridian(f, b, [&](const auto& g, double lo, double hi) {
            return adaptive_gauss_smoothstep(g, lo, hi, inner);
        });
    };
    const double phi0 = std::atan2(L.ih.y, L.ih.x) + 0.5 * pi;
    std::vector<double> a = {phi0, phi0 + pi, phi0 + 2.0 * pi};
    for (double t : dielectric_turning_azimuths(L, eta))
        for (int j = -1; j <= 3; ++j)
            if (t + j * pi > phi0 && t + j * pi < phi0 + 2.0 * pi)
                a.push_back(t + j * pi);
    std::sort(a.begin(), a.end());
    double sum = 0.0;
    for (size_t k = 0; k + 1 < a.size(); ++k)
        sum += adaptive_gauss_smoothstep(meridian, a[k], a[k + 1], outer);
    return sum;
}

}  // namespace ggxref::detail
