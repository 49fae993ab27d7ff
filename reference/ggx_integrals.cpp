// ggx_integrals.cpp - reflected radiance of the GGX BRDF under a lobe or a disk light. Both are
// integrated in polar coordinates (beta, gamma) about the light's axis l over the cap beta <= R
// (R = pi/2 for the lobe, the radius for the disk), so the lobe's support and the disk's edge are
// limits of integration. Each meridian is cut at the horizon (where brdf_cos has its kink) and
// split where it passes closest to the BRDF peak, the mirror direction r of i; the azimuth gamma
// is measured from r and split there and where the horizon crosses the cap's edge.
#include "ggx_integrals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ggx_adaptive.hpp"
#include "ggx_quadrature.hpp"
#include "ggx_standard_space.hpp"

namespace ggxref {
namespace {

constexpr double pi = 3.14159265358979323846;

// The cap of polar radius R about l with the frame o = cos b l + sin b (cos g u + sin g v); u
// points towards the peak r (gamma = 0 there). The light on the cap is cos(b)^exponent.
struct Cap {
    double ax, ay;
    Vec3 i, r;     // view and its mirror direction
    Vec3 l, u, v;  // frame about the light's axis
    double R, exponent;
};

Cap make_cap(const Params& p, const Vec3& l, double R, double exponent)
{
    const Vec3 r{-p.i.x, -p.i.y, p.i.z};
    const Vec3 t = r - dot(r, l) * l;  // r's part across l: its azimuth is gamma = 0
    const Vec3 u = length(t) > 1e-9 ? normalize(t) : any_perpendicular(l);
    return {p.ax, p.ay, p.i, r, l, u, cross(l, u), R, exponent};
}

// Where the meridian's beta in (0, R) needs a cut or a split: the horizon oz = lz cos b + wz sin b
// = 0, the point closest to the peak, and for a narrow lobe its width 1/sqrt(k) and 4 times that.
std::vector<double> meridian_breaks(const Cap& c, const Vec3& w)
{
    std::vector<double> b = detail::harmonic_roots(w.z, c.l.z, 0.0, 0.0, c.R);
    b.push_back(std::atan2(dot(c.r, w), dot(c.r, c.l)));
    if (c.exponent > 1.0)
        for (double s : {1.0, 4.0})
            b.push_back(s / std::sqrt(c.exponent));
    b.push_back(0.0);
    b.push_back(c.R);
    std::sort(b.begin(), b.end());
    b.erase(std::remove_if(b.begin(), b.end(), [&](double x) { return x < 0.0 || x > c.R; }), b.end());
    return b;
}

// Tolerances: near a sharp peak at grazing views the integrand carries rounding noise of ~1e-13
// relative (o_xy near -i_xy makes h = normalize(i + o) cancel, and D amplifies h's error by
// 1/alpha), which a tighter inner target would chase down to the maximum depth at every meridian
// (seconds per call at alpha 0.01, 89 degrees). The 10/20-point difference overstates the error
// of the 20-point rule by orders of magnitude: these leave results within ~1e-11 relative.
constexpr detail::Tolerance inner_tol{1e-15, 1e-11}, outer_tol{1e-14, 1e-10};

// int over beta in [0, R] of brdf_cos(i, o) cos(b)^k sin b at azimuth gamma, pieces above the
// horizon only (tested at each piece's midpoint; brdf_cos is 0 below it anyway).
double meridian(const Cap& c, double gamma)
{
    const Vec3 w = std::cos(gamma) * c.u + std::sin(gamma) * c.v;
    auto direction = [&](double b) { return std::cos(b) * c.l + std::sin(b) * w; };
    auto f = [&](double b) {
        const double light = c.exponent == 0.0 ? 1.0 : std::pow(std::cos(b), c.exponent);
        return brdf_cos(c.i, direction(b), c.ax, c.ay) * light * std::sin(b);
    };
    auto from_edge = [&](double x) { return f(c.R - x); };
    const std::vector<double> b = meridian_breaks(c, w);
    double sum = 0.0;
    for (size_t k = 0; k + 1 < b.size(); ++k) {
        if (!(b[k + 1] > b[k]) || direction(0.5 * (b[k] + b[k + 1])).z <= 0.0)
            continue;
        // A lobe ends like (R - b)^k at o.l = 0, singular for fractional k: integrate from the
        // edge with x = (R - b[k]) s^4, which leaves s^(4k + 3).
        if (c.exponent > 0.0 && b[k + 1] == c.R)
            sum += detail::adaptive_gauss_quartic(from_edge, 0.0, c.R - b[k], inner_tol);
        else
            sum += detail::adaptive_gauss(f, b[k], b[k + 1], inner_tol);
    }
    return sum;
}

// int over gamma in [-pi, pi] of the meridians, split at the peak (gamma = 0) and where the
// horizon crosses the cap's edge: lz cos R + sin R (uz cos g + vz sin g) = 0.
double integrate_cap(const Cap& c)
{
    const double sR = std::sin(c.R);
    std::vector<double> g = detail::harmonic_roots(c.v.z * sR, c.u.z * sR, c.l.z * std::cos(c.R), -pi, pi);
    g.insert(g.end(), {-pi, 0.0, pi});
    std::sort(g.begin(), g.end());
    auto f = [&](double gamma) { return meridian(c, gamma); };
    double sum = 0.0;
    for (size_t k = 0; k + 1 < g.size(); ++k)
        sum += detail::adaptive_gauss(f, g[k], g[k + 1], outer_tol);
    return sum;
}

// A unit l (to 1e-9), a finite exponent >= 0, a radius in (0, pi/2]; the uniform light reads neither.
bool valid(const Light& light)
{
    if (light.kind == Light::Kind::uniform)
        return true;
    if (!(std::fabs(length(light.l) - 1.0) <= 1e-9))
        return false;
    if (light.kind == Light::Kind::lobe)
        return light.exponent >= 0.0 && std::isfinite(light.exponent);
    return light.radius > 0.0 && light.radius <= 0.5 * pi;
}

}  // namespace

double light_value(const Light& light, const Vec3& o)
{
    const double c = dot(o, light.l);
    switch (light.kind) {
    case Light::Kind::lobe:
        return c > 0.0 ? (light.exponent == 0.0 ? 1.0 : std::pow(c, light.exponent)) : 0.0;
    case Light::Kind::disk:
        return c >= std::cos(light.radius) ? 1.0 : 0.0;
    default:
        return 1.0;
    }
}

double reflected_radiance(const Params& params, const Light& light)
{
    if (!valid(light))
        return std::numeric_limits<double>::quiet_NaN();
    if (!(params.i.z > 0.0))
        return 0.0;
    if (light.kind == Light::Kind::uniform)
        return albedo({params.ax, params.ay, params.i});  // tangent space, n = z
    if (light.kind == Light::Kind::lobe)
        return integrate_cap(make_cap(params, light.l, 0.5 * pi, light.exponent));
    return integrate_cap(make_cap(params, light.l, light.radius, 0.0));
}

}  // namespace ggxref
