// test_albedo_mc.cpp - the mean furnace weight of each sampler over a fine stratified grid of
// uniforms equals the quadrature albedo: sampler, pdf and albedo checked against each other.
#include <doctest/doctest.h>

#include <string>

#include "ggx_quadrature.hpp"
#include "ref_test_helpers.hpp"

using namespace reftest;

namespace {

struct Node {
    double u, w;
};

// Midpoints of n strata of [lo, hi], uniform or, with graded, after the smoothstep u = lo + (hi - lo)
// (10 s^3 - 15 s^4 + 6 s^5): dense at both ends, where the samplers map their uniforms onto the long
// GGX tail (u -> 1) or through a square root (u -> 0).
std::vector<Node> strata(int n, double lo, double hi, bool graded)
{
    std::vector<Node> nodes;
    for (int k = 0; k < n; ++k) {
        const double s = (k + 0.5) / n;
        if (graded)
            nodes.push_back({lo + (hi - lo) * s * s * s * (10.0 - 15.0 * s + 6.0 * s * s),
                             30.0 * (hi - lo) * s * s * (1.0 - s) * (1.0 - s) / n});
        else
            nodes.push_back({lo + (hi - lo) * s, (hi - lo) / n});
    }
    return nodes;
}

// The tail is at u1 -> 1 for the slope and disk samplers (radius), at u2 -> 1 for the caps family
// (cap height); heitz2017 switches half disks at u2 = 1/(1 + ih.z), each side stratified alone.
double mean_weight(Method method, const Params& p, int n)
{
    const bool tail_in_u1 = method == Method::ndf || method == Method::heitz || method == Method::heitz2017;
    std::vector<Node> u2 = strata(n, 0.0, 1.0, !tail_in_u1);
    if (method == Method::heitz2017) {
        const double split = 1.0 / (1.0 + normalize({p.ax * p.i.x, p.ay * p.i.y, p.i.z}).z);
        u2 = strata(n / 2, 0.0, split, false);
        for (const Node& node : strata(n / 2, split, 1.0, false))
            u2.push_back(node);
    }
    double sum = 0.0;
    for (const Node& a : strata(n, 0.0, 1.0, tail_in_u1))
        for (const Node& b : u2)
            sum += sample(method, p, a.u, b.u).weight * a.w * b.w;
    return sum;
}

}  // namespace

TEST_CASE("stratified mean of the weight = albedo, every method")
{
    double worst = 0.0;
    for (Method method : all_methods)
        for (auto [ax, ay] : std::vector<std::pair<double, double>>{{0.1, 0.1}, {0.5, 0.15}, {1.2, 1.2}})
            for (double theta : {0.0, 45.0, 80.0}) {
                const Params p = params(method, ax, ay, theta);
                const double e = albedo(p), mc = mean_weight(method, p, 256);
                CAPTURE(std::string(method_name(method)));
                CAPTURE(ax);
                CAPTURE(ay);
                CAPTURE(theta);
                CHECK(std::fabs(mc - e) < 1e-4);
                worst = std::max(worst, std::fabs(mc - e));
            }
    MESSAGE("worst |mean weight - albedo| = " << worst);
}
