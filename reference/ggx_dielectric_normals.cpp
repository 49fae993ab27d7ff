// ggx_dielectric_normals.cpp - the lobes of one microfacet normal and the meridian cuts of the
// dielectric's integrals over normals (ggx_dielectric_normals.hpp). With w = A ms the unnormalized
// normal (A = diag(ax, ay, 1)), the critical angle and the refracted horizon are zeros of quadratic
// forms w^T M w, so on a meridian, w = sin th u + cos th z, they are roots of a quadratic in tan th.
#include "ggx_dielectric_normals.hpp"

#include <cmath>

namespace ggxref::detail {
namespace {

constexpr double pi = 3.14159265358979323846;

// A symmetric 3 x 3 matrix as the bilinear form it defines.
struct Form {
    double m[3][3];
    double operator()(const Vec3& a, const Vec3& b) const
    {
        const double x[3] = {a.x, a.y, a.z}, y[3] = {b.x, b.y, b.z};
        double sum = 0.0;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                sum += x[r] * m[r][c] * y[c];
        return sum;
    }
};

// The critical angle i.m = c > 0: (i.w)^2 - c^2 |w|^2 = 0, M = i i^T - c^2 I (the squaring adds the
// normals with i.m = -c, harmless extra cuts).
Form critical_form(const Vec3& i, double c)
{
    const double v[3] = {i.x, i.y, i.z};
    Form f{};
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            f.m[r][k] = v[r] * v[k] - (r == k ? c * c : 0.0);
    return f;
}

// The refracted horizon: o_t.z = (-iz + (c - eta cos_t) mz) / eta = 0 with eta cos_t = sqrt(eta^2 - 1 +
// c^2) gives c - iz / mz = sqrt(eta^2 - 1 + c^2); squared and times mz^2, with c = i.w / |w| and
// mz = w.z / |w|: iz^2 |w|^2 - 2 iz (i.w) w.z - (eta^2 - 1) w.z^2 = 0 (the squaring adds the roots of
// the negative square root, harmless extra cuts).
Form refracted_horizon_form(const Vec3& i, double eta)
{
    const double v[3] = {i.x, i.y, i.z}, z[3] = {0.0, 0.0, 1.0}, d = eta * eta - 1.0;
    Form f{};
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            f.m[r][k] = (r == k ? i.z * i.z : 0.0) - i.z * (v[r] * z[k] + z[r] * v[k]) - d * z[r] * z[k];
    return f;
}

// Polar angles th in (0, pi/2) of the meridian phi where w^T M w = 0, w = sin th u + cos th z with
// u = (ax cos phi, ay sin phi, 0): a T^2 + 2 b T + c = 0 for T = tan th > 0.
std::vector<double> meridian_zeros(const Local& L, const Form& f, double phi)
{
    const Vec3 u{L.ax * std::cos(phi), L.ay * std::sin(phi), 0.0}, z{0.0, 0.0, 1.0};
    const double a = f(u, u), b = f(u, z), c = f(z, z);
    std::vector<double> tans;
    if (a == 0.0) {
        if (b != 0.0)
            tans.push_back(-c / (2.0 * b));
    } else {
        const double disc = b * b - a * c;
        if (disc >= 0.0) {
            const double q = -(b + std::copysign(std::sqrt(disc), b));  // no cancellation
            tans.push_back(q / a);
            if (q != 0.0)
                tans.push_back(c / q);
        }
    }
    std::vector<double> out;
    for (double t : tans)
        if (t > 0.0 && std::isfinite(t))
            out.push_back(std::atan(t));
    return out;
}

// Azimuths phi where the meridian touches the curve w^T M w = 0: the quadratic in tan th of
// meridian_zeros has a double root, b(phi)^2 = a(phi) c. With u = cos phi x + sin phi y (x = (ax, 0, 0),
// y = (0, ay, 0)), b^2 - a c is a quadratic form in (cos phi, sin phi), zero for two tan phi at most.
std::vector<double> touching_azimuths(const Local& L, const Form& f)
{
    const Vec3 x{L.ax, 0.0, 0.0}, y{0.0, L.ay, 0.0}, z{0.0, 0.0, 1.0};
    const double p = f(x, z), q = f(y, z), k = f(z, z);
    const double cc = p * p - k * f(x, x), cs = p * q - k * f(x, y), ss = q * q - k * f(y, y);
    std::vector<double> out;
    if (ss == 0.0) {  // the root tan phi = infinity, and one finite one
        out.push_back(0.5 * pi);
        if (cs != 0.0)
            out.push_back(std::atan(-cc / (2.0 * cs)));
        return out;
    }
    const double disc = cs * cs - cc * ss;
    if (disc < 0.0)
        return out;
    const double r = -(cs + std::copysign(std::sqrt(disc), cs));
    out.push_back(std::atan(r / ss));
    if (r != 0.0)
        out.push_back(std::atan(cc / r));
    return out;
}

}  // namespace

Lobes lobes_of(const Vec3& i, const Vec3& m, double eta)
{
    Lobes l{};
    l.c = dot(i, m);
    l.F = l.c > 0.0 ? fresnel_dielectric(l.c, eta) : 1.0;
    l.o_r = reflect(i, m);
    l.cos_t = std::sqrt(std::fmax(0.0, 1.0 - (1.0 - l.c * l.c) / (eta * eta)));
    l.o_t = (-1.0 / eta) * i + (l.c / eta - l.cos_t) * m;
    l.reflects = l.c > 0.0 && l.o_r.z > 0.0;
    l.transmits = l.c > 0.0 && l.cos_t > 0.0 && l.o_t.z < 0.0;
    return l;
}

double refraction_spread(const Lobes& l, double eta)
{
    const double d = 1.0 - eta * eta, sum = l.c + eta * l.cos_t;
    return d * d / (eta * eta * l.cos_t * sum * sum);
}

Local dielectric_problem(const Side& side)
{
    return side.method == Method::caps_iso ? isotropic_problem(side.p) : tangent_problem(side.p);
}

// For eta > 1 a refraction always crosses the surface (o_t.z = (-iz + (c - eta cos_t) mz) / eta
// with c < eta cos_t) and every visible normal refracts, so only i.m = 0 and the reflection's
// horizon cut the meridian.
std::vector<double> dielectric_cuts(const Local& L, double eta, double phi)
{
    std::vector<double> cuts = cuts_visible(L, phi);
    auto add = [&](const std::vector<double>& more) { cuts.insert(cuts.end(), more.begin(), more.end()); };
    add(cuts_horizon(L, phi));
    if (eta < 1.0) {
        add(meridian_zeros(L, critical_form(L.i, std::sqrt(1.0 - eta * eta)), phi));
        add(meridian_zeros(L, refracted_horizon_form(L.i, eta), phi));
    }
    return cuts;
}

std::vector<double> dielectric_turning_azimuths(const Local& L, double eta)
{
    if (eta > 1.0)
        return {};
    std::vector<double> out = touching_azimuths(L, critical_form(L.i, std::sqrt(1.0 - eta * eta)));
    const std::vector<double> more = touching_azimuths(L, refracted_horizon_form(L.i, eta));
    out.insert(out.end(), more.begin(), more.end());
    return out;
}

}  // namespace ggxref::detail
