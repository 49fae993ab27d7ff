// ggx_math.cpp - the shared GGX quantities of docs/MATH.md "Shared quantities": NDF, Smith Lambda and masking,
// projected area, VNDF, the bounded-VNDF k of Eto & Tokuyoshi, and their isotropic world-space forms.
#include <algorithm>
#include <cmath>

#include "ggx_reference.hpp"

namespace ggxref {
namespace {

constexpr double pi = 3.14159265358979323846;
double sq(double x) { return x * x; }

// Smith Lambda from the height wz and t(w); q = t^2 - wz^2 >= 0 is the stretched tangential part,
// so (t/|wz| - 1)/2 = q / (2 |wz| (t + |wz|)) without cancellation. Lambda(-w) = 1 + Lambda(w).
double lambda_from(double wz, double t, double q)
{
    const double up = q / (2.0 * std::fabs(wz) * (t + std::fabs(wz)));
    return wz >= 0.0 ? up : 1.0 + up;
}

// Height-correlated G2 = 1 / (1 + Lambda(i) + Lambda(o)) = 2 iz oz / (t(i) oz + t(o) iz), iz, oz > 0.
double g2_from(double iz, double ti, double oz, double to)
{
    if (iz <= 0.0 || oz <= 0.0)
        return 0.0;
    return 2.0 * iz * oz / (ti * oz + to * iz);
}

}  // namespace

double t_of(const Vec3& w, double ax, double ay) { return std::sqrt(sq(ax * w.x) + sq(ay * w.y) + sq(w.z)); }

// D(m) = 1 / (pi ax ay (mx^2/ax^2 + my^2/ay^2 + mz^2)^2) on the upper hemisphere.
double D(const Vec3& m, double ax, double ay)
{
    if (m.z <= 0.0)
        return 0.0;
    const double e = sq(m.x / ax) + sq(m.y / ay) + sq(m.z);
    return 1.0 / (pi * ax * ay * e * e);
}

double lambda(const Vec3& w, double ax, double ay)
{
    return lambda_from(w.z, t_of(w, ax, ay), sq(ax * w.x) + sq(ay * w.y));
}

// G1(w) = 1 / (1 + Lambda(w)) = 2 wz / (wz + t(w)) for wz > 0.
double G1(const Vec3& w, double ax, double ay) { return w.z > 0.0 ? 2.0 * w.z / (w.z + t_of(w, ax, ay)) : 0.0; }

double G2_height_correlated(const Vec3& i, const Vec3& o, double ax, double ay)
{
    return g2_from(i.z, t_of(i, ax, ay), o.z, t_of(o, ax, ay));
}

double G2_separable(const Vec3& i, const Vec3& o, double ax, double ay) { return G1(i, ax, ay) * G1(o, ax, ay); }

// sigma(i) = (iz + t)/2; for iz < 0 use (iz + t) = q / (t - iz) (bounded supplement, section 3).
double projected_area(const Vec3& i, double ax, double ay)
{
    const double t = t_of(i, ax, ay);
    if (i.z >= 0.0)
        return 0.5 * (i.z + t);
    return 0.5 * (sq(ax * i.x) + sq(ay * i.y)) / (t - i.z);
}

// Dv(m; i) = max(0, i.m) D(m) / sigma(i) (Heitz 2018; docs/MATH.md "Shared quantities").
double vndf_pdf(const Vec3& m, const Vec3& i, double ax, double ay)
{
    return std::max(0.0, dot(i, m)) * D(m, ax, ay) / projected_area(i, ax, ay);
}

// k = (1 - a^2) s^2 / (s^2 + a^2 iz^2), a = min(ax, ay), the bound of supplement Eq. 1 over its
// azimuth at the extreme P = s^2 (docs/MATH.md "bounded"): s = 1 + |i_xy| for a <= 1 (Eto &
// Tokuyoshi 2023), s = 1 - |i_xy| = iz^2 / (1 + |i_xy|) for a > 1, where k < 0; dividing by s^2 / iz^2
// there leaves (1 - a^2) iz^2 / (iz^2 + a^2 (1 + |i_xy|)^2), free of 0/0 at grazing views.
double bounded_k(const Vec3& i, double ax, double ay)
{
    const double a2 = sq(std::min(ax, ay));
    const double w2 = sq(1.0 + std::sqrt(sq(i.x) + sq(i.y))), iz2 = sq(i.z);
    if (a2 <= 1.0)
        return (1.0 - a2) * w2 / (w2 + a2 * iz2);
    return (1.0 - a2) * iz2 / (iz2 + a2 * w2);
}

// f(i, o) oz = D(h) G2(i, o) / (4 iz) with h = normalize(i + o) (Cook-Torrance, Fresnel = 1).
double brdf_cos(const Vec3& i, const Vec3& o, double ax, double ay)
{
    if (i.z <= 0.0 || o.z <= 0.0)
        return 0.0;
    const Vec3 h = normalize(i + o);
    return D(h, ax, ay) * G2_height_correlated(i, o, ax, ay) / (4.0 * i.z);
}

// Isotropic D = alpha^2 / (pi N^2), N = (m.n)^2 (alpha^2 - 1) + 1 = |m x n|^2 + alpha^2 (m.n)^2
// (Benyoub 2024 appendix; the second form avoids cancellation for small alpha).
double D_iso(const Vec3& m, const Vec3& n, double alpha)
{
    const double mz = dot(m, n);
    if (mz <= 0.0)
        return 0.0;
    const Vec3 c = cross(m, n);
    const double N = dot(c, c) + sq(alpha * mz);
    return sq(alpha) / (pi * N * N);
}

double t_iso(const Vec3& w, const Vec3& n, double alpha)
{
    const Vec3 c = cross(w, n);
    return std::sqrt(sq(alpha) * dot(c, c) + sq(dot(w, n)));
}

double G2_height_correlated_iso(const Vec3& i, const Vec3& o, const Vec3& n, double alpha)
{
    return g2_from(dot(i, n), t_iso(i, n, alpha), dot(o, n), t_iso(o, n, alpha));
}

}  // namespace ggxref
