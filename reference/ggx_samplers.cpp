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

// 1 + ih.z for the stretched view ih = (ax ix, ay iy, iz) / L, L = |(ax ix, ay iy, iz)|.  Below the horizon
// the sum cancels as the view nears -n; there it is written as (L + iz) / L = (L^2 - iz^2) / (L (L - iz))
// = (ax^2 ix^2 + ay^2 iy^2) / (L (L - iz)), a quotient of sums of squares.
double one_plus_stretched_z(const Vec3& i, double ax, double ay)
{
    const double tx = ax * i.x, ty = ay * i.y, q = tx * tx + ty * ty;
    const double L = std::sqrt(q + i.z * i.z);
    return i.z >= 0.0 ? 1.0 + i.z / L : q / (L * (L - i.z));
}

// The half vector c + ih of a reflected direction c uniform on the spherical cap z in (-lower, 1] about +z
// (Dupuy-Benyoub Listing 3), the cap's height 1 + lower given.  The cap point is taken from the top down:
// with d = u2 height, z = 1 - d and its radius sqrt(1 - z^2) = sqrt(d (2 - d)), so a thin cap (lower near
// -1) keeps its relative precision; where the cap's lower edge is the view's (lower = ih.z), the half
// vector's height z + ih.z = height - d = (1 - u2) height.
Vec3 cap_half_vector(double u1, double u2, double height, const Vec3& ih, bool edge_is_view)
{
    const double phi = 2.0 * pi * u1;
    const double d = u2 * height;
    const double r = std::sqrt(std::max(0.0, d * (2.0 - d)));
    const double z = edge_is_view ? (1.0 - u2) * height : (1.0 - d) + ih.z;
    return {r * std::cos(phi) + ih.x, r * std::sin(phi) + ih.y, z};
}

// Walter et al. 2007: slope radius r = sqrt(u1 / (1 - u1)), angle 2 pi u2, m = normalize(-slopes, 1).
Vec3 sample_ndf(const Params& p, double u1, double u2)
{
    const double r = std::sqrt(u1 / (1.0 - u1));
    const double phi = 2.0 * pi * u2;
    return normalize({-p.ax * r * std::cos(phi), -p.ay * r * std::sin(phi), 1.0});
}

// Heitz 2018 as refactored in Dupuy-Benyoub Listing 2: disk sample warped onto the projected
// visible hemisphere, lifted along ih, unstretched.  The warp's weight s = (1 + ih.z) / 2 and, below the
// horizon, the lifted point's height along ih and its z are written without the sums that cancel as the
// view nears -n: with w = sqrt(1 - t1^2), w - t2 = s (w - r sin phi), so the height is
// sqrt(s (w - r sin phi)(w + t2)); and z = t2 |ih_xy| - hv |ih.z| = (t2^2 - ih.z^2 w^2) / (t2 |ih_xy| + hv |ih.z|),
// whose numerator (t2 - |ih.z| w)(t2 + |ih.z| w) has t2 - |ih.z| w = s (w + r sin phi) (|ih.z| = 1 - 2 s).
Vec3 sample_heitz(const Params& p, double u1, double u2)
{
    const Vec3 ih = stretch(p.i, p.ax, p.ay);
    const double tmp = ih.x * ih.x + ih.y * ih.y;
    const Vec3 T1 = tmp > 0.0 ? (1.0 / std::sqrt(tmp)) * Vec3{-ih.y, ih.x, 0.0} : Vec3{1.0, 0.0, 0.0};
    const Vec3 T2 = cross(ih, T1);
    const double r = std::sqrt(u1), phi = 2.0 * pi * u2;
    const double t1 = r * std::cos(phi), r_sin = r * std::sin(phi);
    const double s = 0.5 * one_plus_stretched_z(p.i, p.ax, p.ay);
    const double w = std::sqrt(std::max(0.0, (1.0 - t1) * (1.0 + t1)));
    const double t2 = (1.0 - s) * w + s * r_sin;
    const double hv = std::sqrt(std::max(0.0, s * (w - r_sin) * (w + t2)));
    Vec3 mh = t1 * T1 + t2 * T2 + hv * ih;
    if (ih.z < 0.0) {
        const double den = t2 * std::sqrt(tmp) - hv * ih.z;
        mh.z = den > 0.0 ? s * (w + r_sin) * (t2 - ih.z * w) / den : 0.0;
    }
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
    return unstretch(cap_half_vector(u1, u2, one_plus_stretched_z(p.i, p.ax, p.ay), ih, true), p.ax, p.ay);
}

// Eto & Tokuyoshi 2023: the same with the cap cut at z > -k ih.z when iz > 0.
Vec3 sample_bounded(const Params& p, double u1, double u2)
{
    const Vec3 ih = stretch(p.i, p.ax, p.ay);
    if (p.i.z <= 0.0)
        return unstretch(cap_half_vector(u1, u2, one_plus_stretched_z(p.i, p.ax, p.ay), ih, true), p.ax, p.ay);
    const double b = bounded_k(p.i, p.ax, p.ay) * ih.z;
    return unstretch(cap_half_vector(u1, u2, 1.0 + b, ih, false), p.ax, p.ay);
}

// Benyoub 2024: world-space caps sampler for one alpha; the cap about +z is carried onto n by the
// rotation x -> (w.x) w / w.z - x, w = n + (0, 0, 1), and the stretch acts on tangential parts.  The
// half vector is assembled along n and across it: its part along n is the cap's (1 - u2) (1 + ih.n),
// across it the rotated cap point's and ih's tangential parts, alpha i_t / L (nothing cancels near -n),
// and unstretched from those parts.
Vec3 sample_caps_iso(const Params& p, double u1, double u2)
{
    const Vec3 n = normalize(p.n);  // a float normal is unit only to within rounding
    const double alpha = p.ax;
    const double iz = dot(p.i, n);
    const Vec3 it = p.i - iz * n;
    const double L = std::sqrt(alpha * alpha * dot(it, it) + iz * iz);
    const double height = iz >= 0.0 ? 1.0 + iz / L : alpha * alpha * dot(it, it) / (L * (L - iz));
    const Vec3 cstd = cap_half_vector(u1, u2, height, Vec3{0.0, 0.0, 0.0}, true);  // about +z, its tangent part
    const Vec3 w = n + Vec3{0.0, 0.0, 1.0};
    const Vec3 flat{cstd.x, cstd.y, 0.0};
    const Vec3 c_t = (dot(w, flat) / w.z) * w - flat;  // the cap point's tangential part, carried about n
    const Vec3 mh_t = c_t + (alpha / L) * it;
    return normalize(alpha * mh_t + ((1.0 - u2) * height) * n);  // unstretch the tangential part
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
