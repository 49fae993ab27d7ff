// ggx_bin_mass.cpp - a density integrated over bins of equal solid angle (z = cos theta, phi). Each
// bin is integrated over (phi, theta) with dw = sin theta dtheta dphi; every meridian is cut where it
// crosses an edge of the support (a jump or a kink), the bin's phi range where an edge turns or
// meets the bin's latitudes, and both at the singular point.
#include "ggx_bin_mass.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "ggx_adaptive.hpp"

namespace ggxref::detail {
namespace {

constexpr double pi = 3.14159265358979323846;
double wrap_positive(double x) { return x - 2.0 * pi * std::floor(x / (2.0 * pi)); }  // to [0, 2 pi)
bool same(double a, double b) { return std::fabs(a - b) < 1e-12; }

using Segments = std::vector<std::vector<int>>;  // per edge, its segments that meet the bin

// Sorted breakpoints within [lo, hi], those closer than 1e-12 merged.
void keep_sorted_within(std::vector<double>& v, double lo, double hi)
{
    v.erase(std::remove_if(v.begin(), v.end(), [&](double x) { return !(x >= lo && x <= hi); }), v.end());
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end(), same), v.end());
}

void append(std::vector<double>& a, const std::vector<double>& b) { a.insert(a.end(), b.begin(), b.end()); }

// Breakpoints in phi: the bin's ends, the azimuth of the point, and where an edge turns or crosses
// the bin's latitudes.
std::vector<double> phi_cuts(const Support& s, const Segments& segs, double z0, double z1, double phi0, double phi1)
{
    std::vector<double> cuts = {phi0, phi1};
    if (s.has_point)
        cuts.push_back(s.point_phi);
    for (size_t e = 0; e < s.edges.size(); ++e)
        if (!segs[e].empty()) {
            append(cuts, s.edges[e].turning_azimuths(segs[e]));
            append(cuts, s.edges[e].latitude_crossings(segs[e], z0));
            append(cuts, s.edges[e].latitude_crossings(segs[e], z1));
        }
    keep_sorted_within(cuts, phi0, phi1);
    return cuts;
}

// Breakpoints in theta on the meridian phi: the bin's ends, the polar angle of the point, the edges.
std::vector<double> theta_cuts(const Support& s, const Segments& segs, double phi, double th0, double th1)
{
    std::vector<double> cuts = {th0, th1};
    if (s.has_point)
        cuts.push_back(s.point_theta);
    for (size_t e = 0; e < s.edges.size(); ++e)
        if (!segs[e].empty())
            append(cuts, s.edges[e].meridian_crossings(segs[e], phi));
    keep_sorted_within(cuts, th0, th1);
    return cuts;
}

// Inner integral over theta in [a, b]; a piece ending at the polar angle of the point, where the
// density grows like 1 / distance, is mapped by sinh about that end (d: the meridian's distance).
// Rounding makes such densities noisy within ~1e-9 of the point, so these pieces refine only a
// few levels.
template <class F> double theta_piece(const F& f, double a, double b, double at, double d, Tolerance tol)
{
    const int depth = 8;
    if (d > 0.0 && same(a, at))
        return adaptive_gauss_sinh(f, a, b, d, tol, depth);
    if (d > 0.0 && same(b, at)) {
        auto flipped = [&](double x) { return f(a + b - x); };
        return adaptive_gauss_sinh(flipped, a, b, d, tol, depth);
    }
    return adaptive_gauss_smoothstep(f, a, b, tol);
}

// Outer integral over phi in [a, b]: next to the azimuth of the point the meridian integral has a
// logarithmic singularity (quartic map); elsewhere the smoothstep map absorbs the square-root
// behaviour where an edge turns.
template <class F> double phi_piece(const F& meridian, double a, double b, const Support& s, Tolerance tol)
{
    if (s.has_point && same(a, s.point_phi))
        return adaptive_gauss_quartic(meridian, a, b, tol);
    if (s.has_point && same(b, s.point_phi)) {
        auto flipped = [&](double x) { return meridian(a + b - x); };
        return adaptive_gauss_quartic(flipped, a, b, tol);
    }
    return adaptive_gauss_smoothstep(meridian, a, b, tol);
}

// Integral of the density over one bin: outer adaptive over phi, inner over theta, both split at
// the breakpoints above.
double bin_mass(const std::function<double(const Vec3&)>& density, const Support& s, double z0, double z1, double phi0,
                double phi1, double rel_tol)
{
    const double th0 = std::acos(z1), th1 = std::acos(z0);
    Segments segs;
    for (const SphereCurve& edge : s.edges)
        segs.push_back(edge.segments_in(z0, z1, phi0, phi1));
    const Tolerance inner{1e-16, 1e-2 * rel_tol}, outer{1e-14, rel_tol};
    auto meridian = [&](double phi) {
        const double c = std::cos(phi), sn = std::sin(phi);
        auto f = [&](double th) {
            const double st = std::sin(th);
            return density({st * c, st * sn, std::cos(th)}) * st;
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

std::function<Vec3(double)> circle(const Vec3& axis, double height)
{
    const Vec3 e1 = any_perpendicular(axis), e2 = cross(axis, e1);
    const double r = std::sqrt(1.0 - height * height);
    return [=](double psi) { return height * axis + r * std::cos(psi) * e1 + r * std::sin(psi) * e2; };
}

// The bounded sampler draws c on the cap c.z >= -k ih.z (docs/MATH.md "Per method"); its edge carried to m.
std::function<Vec3(double)> bounded_cap_normals(const Params& p)
{
    const Vec3 ih = normalize({p.ax * p.i.x, p.ay * p.i.y, p.i.z});
    const double b = bounded_k(p.i, p.ax, p.ay) * ih.z, r = std::sqrt(1.0 - b * b);
    return [=](double psi) {
        const Vec3 mh = Vec3{r * std::cos(psi), r * std::sin(psi), -b} + ih;
        return normalize({p.ax * mh.x, p.ay * mh.y, mh.z});
    };
}

void set_point(Support& s, const Vec3& point)
{
    const double r = std::hypot(point.x, point.y);
    s.has_point = r > 1e-12;
    s.point_theta = std::atan2(r, point.z);
    s.point_phi = wrap_positive(std::atan2(point.y, point.x));
}

std::vector<double> bin_masses(const std::function<double(const Vec3&)>& density, const Support& s, int nz, int nphi,
                               double rel_tol)
{
    std::vector<double> out(size_t(nz) * size_t(nphi));
    auto rows_from = [&](int first_row, int step) {
        for (int jz = first_row; jz < nz; jz += step)
            for (int jp = 0; jp < nphi; ++jp)
                out[size_t(jz) * nphi + jp] = bin_mass(density, s, -1.0 + 2.0 * jz / nz, -1.0 + 2.0 * (jz + 1) / nz,
                                                       2.0 * pi * jp / nphi, 2.0 * pi * (jp + 1) / nphi, rel_tol);
    };
    // The bins are independent: rows go round-robin to one thread per core, each bin computed
    // exactly as by a single thread.
    const int threads = std::clamp(int(std::thread::hardware_concurrency()), 1, std::max(nz, 1));
    std::vector<std::thread> helpers;
    for (int t = 1; t < threads; ++t)
        helpers.emplace_back(rows_from, t, threads);
    rows_from(0, threads);
    for (std::thread& helper : helpers)
        helper.join();
    return out;
}

}  // namespace ggxref::detail
