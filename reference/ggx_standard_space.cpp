// ggx_standard_space.cpp - frames and closed-form meridian cuts for ggx_standard_space.hpp.
#include "ggx_standard_space.hpp"

#include <cmath>

namespace ggxref::detail {
namespace {

constexpr double pi = 3.14159265358979323846;

Local make_local(double ax, double ay, const Vec3& e1, const Vec3& e2, const Vec3& n, const Vec3& i)
{
    const Vec3 il{dot(i, e1), dot(i, e2), dot(i, n)};
    return {ax, ay, il, normalize({ax * il.x, ay * il.y, il.z}), e1, e2, n};
}

}  // namespace

Local tangent_problem(const Params& p)
{
    return make_local(p.ax, p.ay, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}, p.i);
}

// e1 along the tangential part of i, so the local view is (|i_t|, 0, i.n).
Local isotropic_problem(const Params& p)
{
    // n is normalized first (a float-rounded normal is off unit length by
    // ~1e-8, which would leave a tangential part of i parallel to n), and a
    // tangential part at the rounding level of i has no reliable direction:
    // any perpendicular serves then.
    const Vec3 n = normalize(p.n);
    const Vec3 it = p.i - dot(p.i, n) * n;
    const Vec3 e1 = dot(it, it) > 1e-24 * dot(p.i, p.i) ? normalize(it) : any_perpendicular(n);
    return make_local(p.ax, p.ax, e1, cross(n, e1), n, p.i);
}

// P sin x + Q cos x = R cos(x - d), R = hypot(P, Q), d = atan2(P, Q): x = d +- acos(-C/R) + 2 pi j.
std::vector<double> harmonic_roots(double P, double Q, double C, double lo, double hi)
{
    std::vector<double> out;
    const double R = std::hypot(P, Q);
    if (R == 0.0 || std::fabs(C) > R)
        return out;
    const double d = std::atan2(P, Q), a = std::acos(-C / R);
    for (int j = -2; j <= 2; ++j)
        for (double x : {d + a + 2.0 * pi * j, d - a + 2.0 * pi * j})
            if (x > lo && x < hi)
                out.push_back(x);
    return out;
}

// ih.ms = A sin th + ih.z cos th, A = ih_xy . (cos phi, sin phi).
std::vector<double> cuts_visible(const Local& L, double phi)
{
    const double A = L.ih.x * std::cos(phi) + L.ih.y * std::sin(phi);
    return harmonic_roots(A, L.ih.z, 0.0, 0.0, 0.5 * pi);
}

// ohat = reflect(ih, ms): ohat.z + k ih.z = A sin 2th + ih.z cos 2th + k ih.z (bounded supplement Eq. 1).
std::vector<double> cuts_bounded_cap(const Local& L, double phi, double k)
{
    const double A = L.ih.x * std::cos(phi) + L.ih.y * std::sin(phi);
    std::vector<double> out = harmonic_roots(A, L.ih.z, k * L.ih.z, 0.0, pi);
    for (double& x : out)
        x *= 0.5;
    return out;
}

// On this meridian m = (sin b d, cos b) with azimuth d = (ax cos phi, ay sin phi)/l and
// tan b = l tan th; oz = 2 (i.m) mz - iz = a sin 2b + iz cos 2b with a = i_xy . d.
std::vector<double> cuts_horizon(const Local& L, double phi)
{
    const double dx = L.ax * std::cos(phi), dy = L.ay * std::sin(phi), l = std::hypot(dx, dy);
    std::vector<double> out = harmonic_roots((L.i.x * dx + L.i.y * dy) / l, L.i.z, 0.0, 0.0, pi);
    for (double& x : out)
        x = std::atan2(std::sin(0.5 * x), l * std::cos(0.5 * x));
    return out;
}

}  // namespace ggxref::detail
