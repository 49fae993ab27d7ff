// ref_test_helpers.hpp - parameter grids and small helpers shared by the reference's own tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "ggx_reference.hpp"
#include "ggx_stats.hpp"

namespace reftest {

using namespace ggxref;
constexpr double pi = 3.14159265358979323846;

inline Vec3 direction(double theta_deg, double phi)
{
    const double t = theta_deg * pi / 180.0;
    return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
}

// GGX alphas 0.01 .. 2 with anisotropy up to 1:10, and both alphas above 1 (bounded's k < 0).
inline std::vector<std::pair<double, double>> alpha_grid()
{
    return {{0.01, 0.01}, {0.01, 0.1}, {0.1, 0.01}, {0.3, 0.3}, {1.0, 1.0},
            {2.0, 0.2},   {0.2, 2.0},  {2.0, 2.0},  {0.7, 1.3}, {1.3, 2.0}};
}

inline std::vector<double> view_grid() { return {0.0, 30.0, 60.0, 85.0}; }
// Views below the horizon, for the samplers that handle them.
inline bool handles_below_horizon(Method m)
{
    return m == Method::caps || m == Method::caps_iso || m == Method::bounded;
}

// Tangent-space parameters; caps_iso is isotropic (alpha = ax) with n = (0, 0, 1).
inline Params params(Method m, double ax, double ay, double theta_deg, double phi = 0.6)
{
    return {ax, m == Method::caps_iso ? ax : ay, direction(theta_deg, phi)};
}

inline bool close_rel(double a, double b, double rel)
{
    return std::fabs(a - b) <= rel * std::max(std::fabs(a), std::fabs(b));
}

// Rotation taking +z to n (Rodrigues about z x n); columns are the images of x, y, z.
struct Rotation {
    Vec3 cx, cy, cz;
    Vec3 apply(const Vec3& v) const { return v.x * cx + v.y * cy + v.z * cz; }
    Vec3 inverse(const Vec3& v) const { return {dot(v, cx), dot(v, cy), dot(v, cz)}; }
};

inline Rotation rotation_to(const Vec3& n)
{
    const Vec3 z{0.0, 0.0, 1.0};
    const Vec3 axis = cross(z, n);
    const double s = length(axis), c = n.z;
    if (s == 0.0)
        return {{1, 0, 0}, {0, c, 0}, {0, 0, c}};  // identity or rotation by pi about x
    const Vec3 k = (1.0 / s) * axis;
    auto rot = [&](const Vec3& v) { return c * v + s * cross(k, v) + (1.0 - c) * dot(k, v) * k; };
    return {rot({1, 0, 0}), rot({0, 1, 0}), rot({0, 0, 1})};
}

// A configuration of the per-bin tests (bins of o and of m).
struct BinCase {
    Method method;
    Params p;
};

// Isotropic alpha with the world normal n and a view at theta (degrees) in n's frame.
inline Params rotated(double alpha, double theta, const Vec3& n)
{
    const Rotation R = rotation_to(n);
    return {alpha, alpha, R.apply(direction(theta, 0.4)), n};
}

// The hard cases of the bin tests: small alpha, anisotropy, grazing and normal views (o = -i on a
// bin edge at phi = 0), views below the horizon, rotated normals, a bounded cap whose edge just
// dips into a neighbouring latitude band (alpha (1.5, 0.7), 30 deg), and bounded caps cut above the
// stretched horizon (k < 0: alpha 1.5 at 52 deg, (1.3, 2.0) at 88 deg).
inline std::vector<BinCase> hard_bin_cases()
{
    return {{Method::ndf, params(Method::ndf, 0.05, 0.05, 60.0, 0.0)},
            {Method::ndf, params(Method::ndf, 0.5, 0.05, 30.0)},
            {Method::heitz, params(Method::heitz, 0.05, 0.5, 85.0)},
            {Method::heitz2017, params(Method::heitz2017, 0.3, 0.3, 0.0)},
            {Method::caps, params(Method::caps, 0.05, 0.05, 45.0)},
            {Method::caps, params(Method::caps, 0.8, 0.2, 150.0, 0.0)},
            {Method::caps_iso, rotated(0.05, 70.0, normalize({0.3, -0.5, 0.8}))},
            {Method::caps_iso, rotated(0.6, 120.0, normalize({-0.7, 0.1, -0.2}))},
            {Method::bounded, params(Method::bounded, 0.05, 0.5, 30.0)},
            {Method::bounded, params(Method::bounded, 1.0, 1.0, 0.0)},
            {Method::bounded, params(Method::bounded, 1.5, 0.7, 30.0)},
            {Method::bounded, params(Method::bounded, 0.9, 0.4, 80.0, 0.0)},
            {Method::bounded, params(Method::bounded, 1.5, 1.5, 52.0)},
            {Method::bounded, params(Method::bounded, 1.3, 2.0, 88.0)}};
}

// Histogram of `count` reference samples (their o, or their m when `normals`) of stream `seed`.
inline std::vector<uint64_t> sample_histogram(Method method, const Params& p, size_t count, int nz, int nphi,
                                              uint64_t seed, bool normals)
{
    std::vector<float> x(count), y(count), z(count);
    for (size_t k = 0; k < count; ++k) {
        const auto u = uniforms(seed, k);
        const Vec3 d = normals ? sample_normal(method, p, u[0], u[1]) : sample(method, p, u[0], u[1]).o;
        x[k] = float(d.x), y[k] = float(d.y), z[k] = float(d.z);
    }
    return histogram_directions(x.data(), y.data(), z.data(), count, nz, nphi);
}

}  // namespace reftest
