// stress_grid.cpp - the cases of the stability map.
#include "stress_grid.hpp"

#include <algorithm>
#include <cmath>

#include "reference_bridge.hpp"

namespace ggxapp {

namespace {

constexpr float one_below = 1.0f - 5.9604644775390625e-8f;  // 1 - 2^-24, the largest uniform
constexpr double phi_degrees = 35.0;
constexpr std::size_t random_pairs = 8;
constexpr double pi = 3.14159265358979323846, rad = pi / 180.0;  // rad: one degree in radians

// The view with cos theta = c from n (exactly along, across and against it
// at c = 1, 0, -1), turned by phi about n in the frame (t, b, n).
ggxcl::Vec3 view_about(const ggxref::Vec3& n, double c)
{
    double sin_theta = std::sqrt(std::max(0.0, 1.0 - c * c));
    ggxref::Vec3 t = std::fabs(n.z) == 1.0 ? ggxref::Vec3{1, 0, 0} : ggxref::any_perpendicular(n);
    ggxref::Vec3 b = ggxref::cross(n, t);
    ggxref::Vec3 side = std::cos(phi_degrees * rad) * t + std::sin(phi_degrees * rad) * b;
    ggxref::Vec3 v = c * n + sin_theta * side;
    return {float(v.x), float(v.y), float(v.z)};
}

std::vector<std::array<float, 2>> roughness_pairs(ggxcl::Method method, double a, bool isotropic)
{
    float f = float(a), tiny = float(a * 1e-3);
    if (ggxcl::method_traits(method).isotropic_only || isotropic)
        return {{f, f}};
    return {{f, f}, {f, tiny}, {tiny, f}, {0.0f, f}, {f, 0.0f}};
}

std::vector<ggxref::Vec3> normals_for(ggxcl::Method method)
{
    if (ggxcl::method_traits(method).space != ggxcl::Space::world)
        return {{0, 0, 1}};
    return {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, ggxref::normalize({1, 1, 1}), ggxref::normalize({0.3, -0.2, -0.93})};
}

// The pairs at the edges of [0, 1), then `random_pairs` random ones.
std::vector<std::array<float, 2>> uniform_pairs()
{
    std::vector<std::array<float, 2>> pairs;
    for (float a : {0.0f, 0.5f, one_below})
        for (float b : {0.0f, 0.5f, one_below})
            pairs.push_back({a, b});
    for (std::uint64_t k = 0; k < random_pairs; ++k) {
        std::array<double, 2> u = ggxref::uniforms(2026, k);
        pairs.push_back({float(u[0]), float(u[1])});
    }
    return pairs;
}

// The uniforms that put the cap point c of caps, bounded and caps-iso nearest -v: u2 = 1 - 2^-24
// (the cap's lowest row) and u1 = phi / (2 pi) for the azimuth phi of -v in the cap's frame, on
// the 2^-24 grid of the uniforms. There h = c + v cancels (docs/MATH.md "i.m of a cap sample").
// The tangent-space cap is about +z with v = normalize(ax ix, ay iy, iz); caps-iso draws c' about
// +z and carries it onto n by the half-turn H(x) = (w.x) w / wz - x, w = n + z, so c' = H(-v)
// there, with v the view's tangential part scaled by alpha (the other methods get the
// tangent-space pair).
std::array<float, 2> rim_pair(ggxcl::Method method, const std::array<float, 2>& alpha, const ggxcl::Vec3& view,
                              const ggxref::Vec3& n)
{
    const ggxref::Vec3 i{view.x, view.y, view.z};
    ggxref::Vec3 c{-alpha[0] * i.x, -alpha[1] * i.y, -i.z};
    if (ggxcl::method_traits(method).space == ggxcl::Space::world && n.z > -1.0) {
        const ggxref::Vec3 w = n + ggxref::Vec3{0.0, 0.0, 1.0};
        const double iz = ggxref::dot(i, n);
        const ggxref::Vec3 minus_v = -(alpha[0] * (i - iz * n) + iz * n);
        c = (ggxref::dot(w, minus_v) / w.z) * w - minus_v;
    }
    double u = std::atan2(c.y, c.x) / (2.0 * pi);
    u = std::round((u - std::floor(u)) * 16777216.0) / 16777216.0;
    return {float(u < 1.0 ? u : 0.0), one_below};
}

// The roughness rows alpha = 1e-7 .. 1e2 in half decades and the given view columns.
StressAxes axes_of(const std::vector<double>& cos_theta)
{
    StressAxes axes;
    for (int r = 0; r <= 18; ++r)
        axes.alphas.push_back(std::pow(10.0, -7.0 + 0.5 * r));
    axes.cos_theta = cos_theta;
    for (double c : axes.cos_theta)
        axes.theta_degrees.push_back(std::acos(c) / rad);
    return axes;
}

// The view as a dielectric sees it: mirrored through the surface when below (i.n < 0).
ggxcl::Vec3 view_from_above(const ggxcl::Vec3& view, const ggxref::Vec3& n)
{
    const ggxref::Vec3 i{view.x, view.y, view.z};
    const double height = ggxref::dot(i, n);
    const ggxref::Vec3 v = height < 0.0 ? i - (2.0 * height) * n : i;
    return {float(v.x), float(v.y), float(v.z)};
}

// The uniforms of one case: uniform_pairs, then the rim pair, with u3 = 0; a dielectric's each also
// with u3 = 1/2 (random for the random pairs) and 1 - 2^-24 (u3 = 0 reflects wherever F > 0,
// 1 - 2^-24 refracts wherever F < 1).
struct UniformTriple {
    float u1, u2, u3;
    bool random;  // of the random pairs
};

std::vector<UniformTriple> uniform_triples(const std::array<float, 2>& rim, bool dielectric)
{
    std::vector<std::array<float, 2>> pairs = uniform_pairs();
    const std::size_t first_random = pairs.size() - random_pairs;
    pairs.push_back(rim);
    std::vector<UniformTriple> triples;
    for (std::size_t j = 0; j < pairs.size(); ++j) {
        const bool random = j >= first_random && j < first_random + random_pairs;
        const float middle = random ? float(ggxref::uniforms(2027, j - first_random)[0]) : 0.5f;
        for (float u3 : dielectric ? std::vector<float>{0.0f, middle, one_below} : std::vector<float>{0.0f})
            triples.push_back({pairs[j][0], pairs[j][1], u3, random});
    }
    return triples;
}

// The cases of every eta in `etas` (0: a conductor's), roughness row and view column: per normal and
// roughness pair, each of uniform_triples (a dielectric's rim pair for the view seen from above).
std::vector<StressCase> grid_cases(ggxcl::Method method, const StressAxes& axes, const std::vector<float>& etas,
                                   bool isotropic)
{
    std::vector<StressCase> cases;
    for (float eta : etas)
        for (int row = 0; row < int(axes.alphas.size()); ++row)
            for (int column = 0; column < int(axes.cos_theta.size()); ++column)
                for (const ggxref::Vec3& n : normals_for(method))
                    for (const auto& alpha : roughness_pairs(method, axes.alphas[row], isotropic)) {
                        const ggxcl::Vec3 view = view_about(n, axes.cos_theta[column]);
                        const ggxcl::Vec3 normal{float(n.x), float(n.y), float(n.z)};
                        const ggxcl::Vec3 rim_view = eta != 0.0f ? view_from_above(view, n) : view;
                        for (const UniformTriple& u : uniform_triples(rim_pair(method, alpha, rim_view, n), eta != 0.0f))
                            cases.push_back({alpha[0], alpha[1], view, normal, u.u1, u.u2, row, column, u.u3, eta,
                                             u.random});
                    }
    return cases;
}

} // namespace

StressAxes stress_axes()
{
    return axes_of({1.0, std::cos(30 * rad), std::cos(60 * rad), std::cos(85 * rad), std::cos(89 * rad), 1e-4, 1e-7,
                    0.0, std::cos(95 * rad), std::cos(120 * rad), std::cos(150 * rad), std::cos(170 * rad),
                    std::cos(175 * rad), std::cos(178 * rad), std::cos(179 * rad), std::cos(179.5 * rad),
                    std::cos(179.9 * rad), -1.0});
}

std::vector<StressCase> stress_cases(ggxcl::Method method, const StressAxes& axes, bool isotropic)
{
    return grid_cases(method, axes, {0.0f}, isotropic);
}

std::vector<float> dielectric_etas()
{
    return {1e-3f, 1.0f / 1.5f, 0.9999f, 1.0f - 0x1p-24f, 1.0f + 0x1p-23f, 1.0001f, 1.33f, 1.5f, 2.4f, 10.0f, 100.0f};
}

StressAxes dielectric_axes(const std::vector<float>& etas)
{
    std::vector<double> cos_theta{1.0, -1.0, 1e-4, -1e-4, 1e-7, -1e-7, 0.0};
    for (double degrees : {30.0, 45.0, 60.0, 85.0, 89.0, 91.0, 95.0, 120.0, 135.0, 150.0, 179.0})
        cos_theta.push_back(std::cos(degrees * rad));
    std::sort(cos_theta.begin(), cos_theta.end(), [](double a, double b) { return a > b; });
    StressAxes axes = axes_of(cos_theta);
    axes.etas = etas;
    return axes;
}

std::vector<StressCase> dielectric_cases(ggxcl::Method method, const StressAxes& axes)
{
    return grid_cases(method, axes, axes.etas, false);
}

} // namespace ggxapp
