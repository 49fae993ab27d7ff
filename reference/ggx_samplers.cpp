// ggx_samplers.cpp - the six ways of drawing a microfacet normal m from two uniforms
// (docs/MATH.md "Per method"), each written from its paper: Walter 2007, Heitz 2018 and 2017, Dupuy & Benyoub
// 2023, Benyoub 2024 and Eto & Tokuyoshi 2023.
#include <algorithm>
#include <cmath>

#include "ggx_reference.hpp"

namespace ggxref {
namespace {

constexpr double pi = 3.14159265358979323846;

// Warp to the hemisphere configuration: ih = normalize(ax ix, ay iy, iz) (Dupuy-Benyoub Sec. 2, step 1).
Vec3 stretch(const Vec3& i, double ax, double ay) { return normalize({ax * i.x, ay * i.y, i.z}); }
// Warp a hemisphere normal back to the ellipsoid: m = normalize(ax mh.x, ay mh.y, mh.z) (step 3).
// The standard-space normal is kept at least 1e-30 above the horizon, as the device keeps it: the
// last uniform, 1 - 2^-24, rounds onto the edge of the cap or disk.
Vec3 unstretch(const Vec3& mh, double ax, double ay) { return normalize({ax * mh.x, ay * mh.y, std::max(mh.z, 1e-30)}); }

// Uniform direction on the spherical cap z in (-lower, 1] about +z (Dupuy-Benyoub Listing 3).
Vec3 cap_point(double u1, double u2, double lower)
{
    const double phi = 2.0 * pi * u1;
    const double z = (1.0 - u2) * (1.0 + lower) - lower;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Walter et al. 2007: slope radius r = sqrt(u1 / (1 - u1)), angle 2 pi u2, m = normalize(-slopes, 1).
Vec3 sample_ndf(const Params& p, double u1, double u2)
{
    const double r = std::sqrt(u1 / (1.0 - u1));
    const double phi = 2.0 * pi * u2;
    return normalize({-p.ax * r * std::cos(phi), -p.ay * r * std::sin(phi), 1.0});
}

// Heitz 2018 as refactored in Dupuy-Benyoub Listing 2: disk sample warped onto the projected
// visible hemisphere, lifted along ih, unstretched.
Vec3 sample_heitz(const Params& p, double u1, double u2)
{
    const Vec3 ih = stretch(p.i, p.ax, p.ay);
    const double tmp = ih.x * ih.x + ih.y * ih.y;
    const Vec3 T1 = tmp > 0.0 ? (1.0 / std::sqrt(tmp)) * Vec3{-ih.y, ih.x, 0.0} : Vec3{1.0, 0.0, 0.0};
    const Vec3 T2 = cross(ih, T1);
    const double r = std::sqrt(u1), phi = 2.0 * pi * u2;
    const double t1 = r * std::cos(phi);
    const double s = 0.5 * (1.0 + ih.z);
    const double t2 = (1.0 - s) * std::sqrt(1.0 - t1 * t1) + s * r * std::sin(phi);
    const Vec3 mh = t1 * T1 + t2 * T2 + std::sqrt(std::max(0.0, 1.0 - t1 * t1 - t2 * t2)) * ih;
    return unstretch(mh, p.ax, p.ay);
}

// Heitz 2017 report: the two half disks chosen with probabilities a = 1/(1 + ih.z) and 1 - a
// (Eqs. 1-6), then unstretched. Valid for iz >= 0.
Vec3 sample_heitz2017(const Params& p, double u1, double u2)
{
    const Vec3 V = stretch(p.i, p.ax, p.ay);
    const double tmp = V.x * V.x + V.y * V.y;
    const Vec3 T1 = tmp > 0.0 ? (1.0 / std::sqrt(tmp)) * Vec3{V.y, -V.x, 0.0} : Vec3{1.0, 0.0, 0.0};  // Eq. 1
    const Vec3 T2 = cross(T1, V);                                                                     // Eq. 2
    const double a = 1.0 / (1.0 + V.z);
    const double r = std::sqrt(u1);  // Eq. 3
    const bool upper = u2 < a;
    const double phi = upper ? u2 / a * pi : pi + (u2 - a) / (1.0 - a) * pi;  // Eq. 4
    const double P1 = r * std::cos(phi);
    const double P2 = r * std::sin(phi) * (upper ? 1.0 : V.z);                                 // Eq. 5
    const Vec3 N = P1 * T1 + P2 * T2 + std::sqrt(std::max(0.0, 1.0 - P1 * P1 - P2 * P2)) * V;  // Eq. 6
    return unstretch(N, p.ax, p.ay);
}

// Dupuy & Benyoub 2023: reflected direction c uniform on the cap z > -ih.z, m = halfway(ih, c).
Vec3 sample_caps(const Params& p, double u1, double u2)
{
    const Vec3 ih = stretch(p.i, p.ax, p.ay);
    return unstretch(cap_point(u1, u2, ih.z) + ih, p.ax, p.ay);
}

// Eto & Tokuyoshi 2023: the same with the cap cut at z > -k ih.z when iz > 0.
Vec3 sample_bounded(const Params& p, double u1, double u2)
{
    const Vec3 ih = stretch(p.i, p.ax, p.ay);
    const double b = p.i.z > 0.0 ? bounded_k(p.i, p.ax, p.ay) * ih.z : ih.z;
    return unstretch(cap_point(u1, u2, b) + ih, p.ax, p.ay);
}

// Benyoub 2024: world-space caps sampler for one alpha; the cap about +z is carried onto n by the
// rotation x -> (w.x) w / w.z - x, w = n + (0, 0, 1), and the stretch acts on tangential parts.
Vec3 sample_caps_iso(const Params& p, double u1, double u2)
{
    const Vec3& n = p.n;
    const double alpha = p.ax;
    const double iz = dot(p.i, n);
    const Vec3 ih = normalize(alpha * (p.i - iz * n) + iz * n);  // stretch the tangential part
    const Vec3 cstd = cap_point(u1, u2, dot(ih, n));
    const Vec3 w = n + Vec3{0.0, 0.0, 1.0};
    const Vec3 c = (dot(w, cstd) / w.z) * w - cstd;  // cap about n
    const Vec3 mh = c + ih;
    const double mhz = dot(n, mh);
    return normalize(alpha * (mh - mhz * n) + mhz * n);  // unstretch the tangential part
}

}  // namespace

Vec3 sample_normal(Method method, const Params& p, double u1, double u2)
{
    switch (method) {
    case Method::ndf:
        return sample_ndf(p, u1, u2);
    case Method::heitz:
        return sample_heitz(p, u1, u2);
    case Method::heitz2017:
        return sample_heitz2017(p, u1, u2);
    case Method::caps:
        return sample_caps(p, u1, u2);
    case Method::caps_iso:
        return sample_caps_iso(p, u1, u2);
    case Method::bounded:
        return sample_bounded(p, u1, u2);
    }
    return {0.0, 0.0, 0.0};
}

}  // namespace ggxref
