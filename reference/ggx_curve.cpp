// ggx_curve.cpp - sampling, turning points and crossings of a closed curve on the sphere.
#include "ggx_curve.hpp"

#include <algorithm>
#include <cmath>

namespace ggxref::detail {
namespace {

constexpr double pi = 3.14159265358979323846;
double wrap(double x) { return x - 2.0 * pi * std::floor((x + pi) / (2.0 * pi)); }    // to [-pi, pi)
double wrap_positive(double x) { return x - 2.0 * pi * std::floor(x / (2.0 * pi)); }  // to [0, 2 pi)
constexpr double flat = 1e-14;  // height steps below this are rounding, not turns

}  // namespace

SphereCurve::SphereCurve(std::function<Vec3(double)> at, int samples) : at_(std::move(at))
{
    for (int k = 0; k < samples; ++k)
        pts_.push_back(point(2.0 * pi * k / samples));
    add_turns(samples);
    std::sort(pts_.begin(), pts_.end(), [](const Point& a, const Point& b) { return a.psi < b.psi; });
}

SphereCurve::Point SphereCurve::point(double psi) const
{
    const Vec3 v = at_(psi);
    const double r = std::hypot(v.x, v.y);
    return {wrap_positive(psi), v.z, std::atan2(v.y, v.x), std::atan2(r, v.z), false};
}

template <class G> SphereCurve::Point SphereCurve::golden_max(double a, double b, const G& g) const
{
    const double r = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - r * (b - a), d = a + r * (b - a);
    double gc = g(point(c)), gd = g(point(d));
    for (int it = 0; it < 80 && b - a > 1e-15; ++it) {
        if (gc > gd) {  // the maximum lies in [a, d]
            b = d;
            d = c;
            gd = gc;
            c = b - r * (b - a);
            gc = g(point(c));
        } else {  // in [c, b]
            a = c;
            c = d;
            gc = gd;
            d = a + r * (b - a);
            gd = g(point(d));
        }
    }
    return point(0.5 * (a + b));
}

template <class G> SphereCurve::Point SphereCurve::bisect(Point a, Point b, const G& g) const
{
    double lo = a.psi, hi = b.psi < a.psi ? b.psi + 2.0 * pi : b.psi;
    const bool lo_negative = g(a) < 0.0;
    for (int it = 0; it < 64 && hi - lo > 1e-15; ++it) {
        const double mid = 0.5 * (lo + hi);
        ((g(point(mid)) < 0.0) == lo_negative ? lo : hi) = mid;
    }
    return point(0.5 * (lo + hi));
}

// Where the azimuth step or the height step changes sign between sample k-1, k, k+1, refine the
// extremum on [psi_{k-1}, psi_{k+1}] and store it as an extra point.
void SphereCurve::add_turns(int samples)
{
    const double step = 2.0 * pi / samples;
    for (int k = 0; k < samples; ++k) {
        const Point prev = pts_[(k + samples - 1) % samples];  // copies: pts_ grows below
        const Point cur = pts_[k];
        const Point next = pts_[(k + 1) % samples];
        const double a = cur.psi - step, b = cur.psi + step;
        const double dphi0 = wrap(cur.phi - prev.phi), dphi1 = wrap(next.phi - cur.phi);
        if (dphi0 * dphi1 < 0.0) {
            const double sign = dphi0 > 0.0 ? 1.0 : -1.0, ref = cur.phi;
            Point t = golden_max(a, b, [&](const Point& p) { return sign * wrap(p.phi - ref); });
            t.turns = true;
            pts_.push_back(t);
        }
        const double dz0 = cur.z - prev.z, dz1 = next.z - cur.z;
        if (dz0 * dz1 < 0.0 && std::fabs(dz0) > flat && std::fabs(dz1) > flat) {
            const double sign = dz0 > 0.0 ? 1.0 : -1.0;
            pts_.push_back(golden_max(a, b, [&](const Point& p) { return sign * p.z; }));
        }
    }
}

std::vector<int> SphereCurve::segments_in(double z0, double z1, double phi0, double phi1) const
{
    const double eps = 1e-9;
    std::vector<int> out;
    const int n = int(pts_.size());
    for (int k = 0; k < n; ++k) {
        const Point& a = pts_[k];
        const Point& b = pts_[(k + 1) % n];
        if (std::max(a.z, b.z) < z0 - eps || std::min(a.z, b.z) > z1 + eps)
            continue;
        const double d = wrap(b.phi - a.phi);
        const double lo = wrap_positive(d > 0.0 ? a.phi : b.phi), hi = lo + std::fabs(d);
        for (double s : {-2.0 * pi, 0.0, 2.0 * pi})
            if (lo + s <= phi1 + eps && hi + s >= phi0 - eps) {
                out.push_back(k);
                break;
            }
    }
    return out;
}

std::vector<double> SphereCurve::turning_azimuths(const std::vector<int>& segments) const
{
    std::vector<double> out;
    const int n = int(pts_.size());
    for (int k : segments)
        for (const Point* p : {&pts_[k], &pts_[(k + 1) % n]})
            if (p->turns)
                out.push_back(wrap_positive(p->phi));
    return out;
}

std::vector<double> SphereCurve::latitude_crossings(const std::vector<int>& segments, double z) const
{
    std::vector<double> out;
    const int n = int(pts_.size());
    auto g = [z](const Point& p) { return p.z - z; };
    for (int k : segments) {
        const Point& a = pts_[k];
        const Point& b = pts_[(k + 1) % n];
        if ((g(a) < 0.0) == (g(b) < 0.0) || std::max(std::fabs(g(a)), std::fabs(g(b))) < flat)
            continue;
        out.push_back(wrap_positive(bisect(a, b, g).phi));
    }
    return out;
}

std::vector<double> SphereCurve::meridian_crossings(const std::vector<int>& segments, double phi) const
{
    std::vector<double> out;
    const int n = int(pts_.size());
    auto g = [phi](const Point& p) { return wrap(p.phi - phi); };
    for (int k : segments) {
        const Point& a = pts_[k];
        const Point& b = pts_[(k + 1) % n];
        if ((g(a) < 0.0) == (g(b) < 0.0) || std::fabs(g(a)) + std::fabs(g(b)) >= pi)
            continue;
        out.push_back(bisect(a, b, g).theta);
    }
    return out;
}

}  // namespace ggxref::detail
