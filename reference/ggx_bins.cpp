// ggx_bins.cpp - probability of o per bin of equal solid angle (z = cos theta, phi), for chi-square
// tests of sampled histograms. Each bin is integrated over (phi, theta) with do = sin theta
// dtheta dphi; every meridian is cut where it crosses the edge of the pdf's support (a jump), the
// bin's phi range where that edge turns or meets the bin's latitudes, and both at o = -i.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "ggx_adaptive.hpp"
#include "ggx_curve.hpp"
#include "ggx_quadrature.hpp"

namespace ggxref {
namespace {

using detail::SphereCurve;
using detail::Tolerance;
constexpr double pi = 3.14159265358979323846;
double wrap_positive(double x) { return x - 2.0 * pi * std::floor(x / (2.0 * pi)); }  // to [0, 2 pi)
bool same(double a, double b) { return std::fabs(a - b) < 1e-12; }

// Where pdf_o jumps (edge) and where it is singular or has a corner (o = -i).
struct Support {
    std::optional<SphereCurve> edge;
    bool has_point = false;
    double point_theta = 0.0, point_phi = 0.0;
};

// The circle of unit o with o.axis = height.
std::function<Vec3(double)> circle(const Vec3& axis, double height)
{
    const Vec3 e1 = any_perpendicular(axis), e2 = cross(axis, e1);
    const double r = std::sqrt(1.0 - height * height);
    return [=](double psi) { return height * axis + r * std::cos(psi) * e1 + r * std::sin(psi) * e2; };
}

// Edge of the bounded cap: the stretched reflections ohat with ohat.z = -k ih.z, carried to o.
std::function<Vec3(double)> bounded_edge(const Params& p)
{
    const Vec3 ih = normalize({p.ax * p.i.x, p.ay * p.i.y, p.i.z});
    const double b = bounded_k(p.i, p.ax, p.ay) * ih.z, r = std::sqrt(1.0 - b * b);
    return [=](double psi) {
        const Vec3 mh = Vec3{r * std::cos(psi), r * std::sin(psi), -b} + ih;
        return reflect(p.i, normalize({p.ax * mh.x, p.ay * mh.y, mh.z}));
    };
}

// NDF sampling has full support; the caps family is supported on o.n > -i.n, except the bounded
// sampler above the horizon, whose support is the image of its cap.
Support support_of(Method method, const Params& p)
{
    Support s;
    const Vec3 n = method == Method::caps_iso ? p.n : Vec3{0.0, 0.0, 1.0};
    const double iz = dot(p.i, n);
    if (method == Method::bounded && iz > 0.0 && bounded_k(p.i, p.ax, p.ay) < 1.0)
        s.edge.emplace(bounded_edge(p));
    else if (method != Method::ndf && std::fabs(iz) < 1.0)
        s.edge.emplace(circle(n, -iz));
    const Vec3 c = -p.i;
    const double r = std::hypot(c.x, c.y);
    s.has_point = r > 1e-12;
    s.point_theta = std::atan2(r, c.z);
    s.point_phi = wrap_positive(std::atan2(c.y, c.x));
    return s;
}

// Sorted breakpoints within [lo, hi], those closer than 1e-12 merged.
void keep_sorted_within(std::vector<double>& v, double lo, double hi)
{
    v.erase(std::remove_if(v.begin(), v.end(), [&](double x) { return !(x >= lo && x <= hi); }), v.end());
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end(), same), v.end());
}

// Breakpoints in phi: the bin's ends, the azimuth of o = -i, and where the edge turns or crosses
// the bin's latitudes.
std::vector<double> phi_cuts(const Support& s, const std::vector<int>& segs, double z0, double z1, double phi0,
                             double phi1)
{
    std::vector<double> cuts = {phi0, phi1};
    if (s.has_point)
        cuts.push_back(s.point_phi);
    if (!segs.empty())
        for (const auto& more : {s.edge->turning_azimuths(segs), s.edge->latitude_crossings(segs, z0),
                                 s.edge->latitude_crossings(segs, z1)})
            cuts.insert(cuts.end(), more.begin(), more.end());
    keep_sorted_within(cuts, phi0, phi1);
    return cuts;
}

// Breakpoints in theta on the meridian phi: the bin's ends, the polar angle of o = -i, the edge.
std::vector<double> theta_cuts(const Support& s, const std::vector<int>& segs, double phi, double th0, double th1)
{
    std::vector<double> cuts = {th0, th1};
    if (s.has_point)
        cuts.push_back(s.point_theta);
    if (!segs.empty()) {
        const std::vector<double> more = s.edge->meridian_crossings(segs, phi);
        cuts.insert(cuts.end(), more.begin(), more.end());
    }
    keep_sorted_within(cuts, th0, th1);
    return cuts;
}

// Inner integral over theta in [a, b]; a piece ending at the polar angle of o = -i, where the NDF-
// sampling pdf grows like 1 / distance, is mapped by sinh about that end (d: the meridian's distance).
// Rounding makes pdf_o noisy within ~1e-9 of o = -i, so these pieces refine only a few levels.
template <class F> double theta_piece(const F& f, double a, double b, double at, double d, Tolerance tol)
{
    const int depth = 8;
    if (d > 0.0 && same(a, at))
        return detail::adaptive_gauss_sinh(f, a, b, d, tol, depth);
    if (d > 0.0 && same(b, at)) {
        auto flipped = [&](double x) { return f(a + b - x); };
        return detail::adaptive_gauss_sinh(flipped, a, b, d, tol, depth);
    }
    return detail::adaptive_gauss_smoothstep(f, a, b, tol);
}

// Outer integral over phi in [a, b]: next to the azimuth of o = -i the meridian integral has a
// logarithmic singularity (quartic map); elsewhere the smoothstep map absorbs the square-root
// behaviour where the edge turns.
template <class F> double phi_piece(const F& meridian, double a, double b, const Support& s, Tolerance tol)
{
    if (s.has_point && same(a, s.point_phi))
        return detail::adaptive_gauss_quartic(meridian, a, b, tol);
    if (s.has_point && same(b, s.point_phi)) {
        auto flipped = [&](double x) { return meridian(a + b - x); };
        return detail::adaptive_gauss_quartic(flipped, a, b, tol);
    }
    return detail::adaptive_gauss_smoothstep(meridian, a, b, tol);
}

// Integral of pdf over one bin: outer adaptive over phi, inner over theta, both split at the
// breakpoints above.
double bin_mass(const std::function<double(const Vec3&)>& pdf, const Support& s, double z0, double z1, double phi0,
                double phi1, double rel_tol)
{
    const double th0 = std::acos(z1), th1 = std::acos(z0);
    const std::vector<int> segs = s.edge ? s.edge->segments_in(z0, z1, phi0, phi1) : std::vector<int>{};
    const Tolerance inner{1e-16, 1e-2 * rel_tol}, outer{1e-14, rel_tol};
    auto meridian = [&](double phi) {
        const double c = std::cos(phi), sn = std::sin(phi);
        auto f = [&](double th) {
            const double st = std::sin(th);
            return pdf({st * c, st * sn, std::cos(th)}) * st;
        };
        const double d = s.has_point ? std::fabs(std::sin(s.point_theta) * std::sin(phi - s.point_phi)) : 0.0;
        const std::vector<double> cuts = theta_cuts(s, segs, phi, th0, th1);
        double sum = 0.0;
        for (size_t k = 0; k + 1 < cuts.size(); ++k)
            sum += theta_piece(f, cuts[k], cuts[k + 1], s.point_theta, d, inner);
        return sum;
    };
    const std::vector<double> cuts = phi_cuts(s, segs, z0, z1, phi0, phi1);
    double sum = 0.0;
    for (size_t k = 0; k + 1 < cuts.size(); ++k)
        sum += phi_piece(meridian, cuts[k], cuts[k + 1], s, outer);
    return sum;
}

}  // namespace

std::vector<double> bin_probabilities(Method method, const Params& p, int nz, int nphi, double rel_tol)
{
    const Support s = support_of(method, p);
    auto pdf = [&](const Vec3& o) { return pdf_o(method, p, o); };
    std::vector<double> out(size_t(nz) * size_t(nphi));
    for (int jz = 0; jz < nz; ++jz)
        for (int jp = 0; jp < nphi; ++jp)
            out[size_t(jz) * nphi + jp] = bin_mass(pdf, s, -1.0 + 2.0 * jz / nz, -1.0 + 2.0 * (jz + 1) / nz,
                                                   2.0 * pi * jp / nphi, 2.0 * pi * (jp + 1) / nphi, rel_tol);
    return out;
}

std::vector<double> bin_probabilities(Method method, const Params& p, int nz, int nphi)
{
    return bin_probabilities(method, p, nz, nphi, 1e-8);
}

}  // namespace ggxref
