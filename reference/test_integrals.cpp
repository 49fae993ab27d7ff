// test_integrals.cpp - reflected radiance under a lobe and a disk light: the hemisphere limits equal
// the albedo, the integration about the light's axis agrees with an independent one about the BRDF
// peak, narrow lights reduce to a point value, the caps sampler's Monte Carlo estimate agrees within
// 5 standard errors (and rejects a wrong light), and light_value's edge cases.
#include <doctest/doctest.h>

#include <string>

#include "ggx_adaptive.hpp"
#include "ggx_integrals.hpp"
#include "ggx_quadrature.hpp"
#include "ggx_standard_space.hpp"
#include "ref_test_helpers.hpp"

using namespace reftest;
using ggxref::detail::adaptive_gauss;
using ggxref::detail::harmonic_roots;
using ggxref::detail::Tolerance;

namespace {

Light lobe(const Vec3& l, double exponent)
{
    Light light;
    light.kind = Light::Kind::lobe;
    light.l = l;
    light.exponent = exponent;
    return light;
}

Light disk(const Vec3& l, double radius)
{
    Light light;
    light.kind = Light::Kind::disk;
    light.l = l;
    light.radius = radius;
    return light;
}

constexpr double deg = pi / 180.0;

// The mirror direction of the view direction(theta, 0.6) of reftest::params, tilted by `extra`
// degrees further from n.
Vec3 mirror(double theta_deg, double extra_deg = 0.0)
{
    const Vec3 d = direction(theta_deg + extra_deg, 0.6);
    return {-d.x, -d.y, d.z};
}

// ---- An independent integration: polar angles (b, g) about the mirror direction r of i (the BRDF
// peak at the pole), each meridian cut where the light jumps or ends (o.l = c: c = cos radius for
// the disk, 0 for the lobe) and ended at the horizon; the azimuth cut where a meridian touches
// the light's edge and through the two points where that edge crosses the horizon.

double light_edge(const Light& light) { return light.kind == Light::Kind::disk ? std::cos(light.radius) : 0.0; }

struct PeakFrame {
    Vec3 r, u, v;
};

double peak_meridian(const Params& p, const Light& light, const PeakFrame& F, double g)
{
    const Vec3 w = std::cos(g) * F.u + std::sin(g) * F.v;
    auto o = [&](double b) { return std::cos(b) * F.r + std::sin(b) * w; };
    auto f = [&](double b) { return brdf_cos(p.i, o(b), p.ax, p.ay) * light_value(light, o(b)) * std::sin(b); };
    std::vector<double> b = harmonic_roots(dot(w, light.l), dot(F.r, light.l), -light_edge(light), 0.0, pi);
    const std::vector<double> h = harmonic_roots(w.z, F.r.z, 0.0, 0.0, pi);  // r.z = iz > 0 at b = 0
    const double top = h.empty() ? pi : *std::min_element(h.begin(), h.end());
    b.insert(b.end(), {0.0, top});
    std::sort(b.begin(), b.end());
    double sum = 0.0;
    for (size_t k = 0; k + 1 < b.size() && b[k + 1] <= top; ++k)
        if (b[k + 1] > b[k] && light_value(light, o(0.5 * (b[k] + b[k + 1]))) > 0.0)
            sum += adaptive_gauss(f, b[k], b[k + 1], Tolerance{1e-16, 1e-12});
    return sum;
}

// Azimuths of the meridians tangent to the edge circle o.l = c (there w.l = +-sqrt(c^2 - (r.l)^2))
// and of the points where the edge crosses the horizon (o.z = 0, o.l = c).
std::vector<double> peak_azimuth_cuts(const Light& light, const PeakFrame& F)
{
    const Vec3& l = light.l;
    const double c = light_edge(light), a = dot(F.r, l), d2 = c * c - a * a;
    std::vector<double> g{-pi, 0.0, pi};
    for (double s : {-1.0, 1.0})
        if (d2 >= 0.0)
            for (double x : harmonic_roots(dot(F.v, l), dot(F.u, l), -s * std::sqrt(d2), -pi, pi))
                g.push_back(x);
    const double h2 = l.x * l.x + l.y * l.y;
    if (h2 > c * c) {
        const Vec3 base{l.x * c / h2, l.y * c / h2, 0.0}, t{-l.y, l.x, 0.0};
        for (double s : {-1.0, 1.0}) {
            const Vec3 q = base + s * std::sqrt((1.0 - c * c / h2) / h2) * t;
            g.push_back(std::atan2(dot(q, F.v), dot(q, F.u)));
        }
    }
    std::sort(g.begin(), g.end());
    return g;
}

double radiance_about_peak(const Params& p, const Light& light)
{
    const Vec3 r{-p.i.x, -p.i.y, p.i.z}, u = any_perpendicular(r);
    const PeakFrame F{r, u, cross(r, u)};
    const std::vector<double> g = peak_azimuth_cuts(light, F);
    auto meridian = [&](double x) { return peak_meridian(p, light, F, x); };
    double sum = 0.0;
    for (size_t k = 0; k + 1 < g.size(); ++k)
        sum += adaptive_gauss(meridian, g[k], g[k + 1], Tolerance{1e-15, 1e-11});
    return sum;
}

// ---- Monte Carlo: mean and standard error of weight * L(o) over n caps samples of stream seed.
struct Estimate {
    double mean, se;
};

std::vector<Estimate> monte_carlo(const Params& p, const std::vector<Light>& lights, size_t n, uint64_t seed)
{
    std::vector<double> sum(lights.size(), 0.0), sum2(lights.size(), 0.0);
    for (size_t k = 0; k < n; ++k) {
        const auto u = uniforms(seed, k);
        const Sample s = sample(Method::caps, p, u[0], u[1]);
        for (size_t j = 0; j < lights.size(); ++j) {
            const double x = s.weight * light_value(lights[j], s.o);
            sum[j] += x;
            sum2[j] += x * x;
        }
    }
    std::vector<Estimate> out;
    for (size_t j = 0; j < lights.size(); ++j) {
        const double mean = sum[j] / n, var = std::max(0.0, sum2[j] / n - mean * mean);
        out.push_back({mean, std::sqrt(var / (n - 1.0))});
    }
    return out;
}

}  // namespace

TEST_CASE("the hemisphere lights (lobe of exponent 0 and disk of radius pi/2 about n) give the albedo")
{
    double worst = 0.0;
    for (double alpha : {0.02, 0.1, 0.3, 1.0, 2.0})
        for (double theta : {0.0, 30.0, 60.0, 85.0}) {
            CAPTURE(alpha);
            CAPTURE(theta);
            const Params p = params(Method::caps, alpha, alpha, theta);
            const double e = albedo(p);
            const double from_lobe = reflected_radiance(p, lobe({0, 0, 1}, 0.0));
            const double from_disk = reflected_radiance(p, disk({0, 0, 1}, 0.5 * pi));
            CHECK(close_rel(from_lobe, e, 1e-9));
            CHECK(close_rel(from_disk, e, 1e-9));
            CHECK(reflected_radiance(p, Light{}) == e);
            worst = std::max({worst, std::fabs(from_lobe / e - 1.0), std::fabs(from_disk / e - 1.0)});
        }
    MESSAGE("worst relative |I - albedo| of the hemisphere lights = " << worst);
}

TEST_CASE("integration about the light's axis = independent integration about the BRDF peak (1e-8)")
{
    // Narrow and wide lobes and disks, on and off the peak, crossing the horizon and (l.z < 0)
    // centred below it; alpha 0.01 .. 1 with anisotropy; views 0 .. 89 degrees.
    const std::vector<std::pair<double, double>> alphas{{0.01, 0.01}, {0.05, 0.05}, {0.02, 0.2}, {0.3, 0.3}, {1.0, 0.6}};
    double worst = 0.0;
    for (auto [ax, ay] : alphas)
        for (double theta : {0.0, 45.0, 80.0, 89.0}) {
            const Params p = params(Method::caps, ax, ay, theta);
            const std::vector<Light> lights{lobe(mirror(theta), 16.0), lobe(normalize({0.3, -0.2, 0.9}), 1.0),
                                            lobe(normalize({-0.5, 0.7, -0.1}), 2.5), disk(mirror(theta, 5.0), 10.0 * deg),
                                            disk(mirror(theta, -2.0), 0.05), disk(normalize({0.6, 0.1, -0.2}), 1.2)};
            for (size_t j = 0; j < lights.size(); ++j) {
                CAPTURE(ax);
                CAPTURE(ay);
                CAPTURE(theta);
                CAPTURE(j);
                const double a = reflected_radiance(p, lights[j]), b = radiance_about_peak(p, lights[j]);
                CHECK(b > 0.0);
                CHECK(std::fabs(a - b) <= std::max(1e-8 * b, 1e-13));
                worst = std::max(worst, std::fabs(a - b) / b);
            }
        }
    MESSAGE("worst relative difference of the two integrations = " << worst);
}

TEST_CASE("narrow lights reduce to a point value: I -> brdf_cos(i, l) times the light's solid-angle weight")
{
    const Params p = params(Method::caps, 0.5, 0.3, 40.0);
    const Vec3 l = normalize({-0.4, -0.1, 0.8});
    const double f = brdf_cos(p.i, l, p.ax, p.ay);
    const double small = 1e-3, k = 1e5;  // errors O(small^2) and O(1/k) relative
    CHECK(close_rel(reflected_radiance(p, disk(l, small)), f * 2.0 * pi * (1.0 - std::cos(small)), 1e-5));
    CHECK(close_rel(reflected_radiance(p, lobe(l, k)), f * 2.0 * pi / (k + 1.0), 1e-3));
    CHECK(!close_rel(reflected_radiance(p, disk(l, small)), f * 2.0 * pi * (1.0 - std::cos(1.01 * small)), 1e-5));
}

TEST_CASE("Monte Carlo with the caps sampler agrees within 5 standard errors; a 12-degree disk is rejected")
{
    const size_t n = size_t(1) << 20;
    std::string rejected;
    double worst = 0.0;
    uint64_t seed = 7;
    for (double alpha : {0.05, 0.3, 1.0})
        for (double theta : {0.0, 45.0, 80.0}) {
            CAPTURE(alpha);
            CAPTURE(theta);
            const Params p = params(Method::caps, alpha, alpha, theta);
            const Light lobe16 = lobe(mirror(theta), 16.0), disk10 = disk(mirror(theta, 5.0), 10.0 * deg);
            const std::vector<Estimate> mc = monte_carlo(p, {lobe16, disk10}, n, seed++);
            const double z_lobe = std::fabs(mc[0].mean - reflected_radiance(p, lobe16)) / mc[0].se;
            const double z_disk = std::fabs(mc[1].mean - reflected_radiance(p, disk10)) / mc[1].se;
            CHECK(z_lobe < 5.0);
            CHECK(z_disk < 5.0);
            worst = std::max({worst, z_lobe, z_disk});
            // Negative control: the 10-degree disk's estimate against the 12-degree disk's integral.
            const double z_wrong = std::fabs(mc[1].mean - reflected_radiance(p, disk(disk10.l, 12.0 * deg))) / mc[1].se;
            if (z_wrong > 5.0)
                rejected += " (" + std::to_string(alpha).substr(0, 4) + ", " + std::to_string(int(theta)) +
                            "): z " + std::to_string(z_wrong) + ";";
        }
    MESSAGE("worst |MC - I| / se = " << worst << "; the 12-degree disk is rejected at (alpha, theta):" << rejected);
    CHECK(!rejected.empty());
}

TEST_CASE("light_value and reflected_radiance edge cases")
{
    const Vec3 n{0, 0, 1}, up = normalize({0.3, 0.4, 0.8}), down = normalize({0.3, 0.4, -0.8});
    // Lobe: the hemisphere o.l > 0 at exponent 0 (0 on and below its edge), cos^k above it.
    CHECK(light_value(lobe(n, 0.0), up) == 1.0);
    CHECK(light_value(lobe(n, 0.0), down) == 0.0);
    CHECK(light_value(lobe(n, 0.0), {1, 0, 0}) == 0.0);
    CHECK(light_value(lobe(n, 2.0), {0.6, 0, 0.8}) == doctest::Approx(0.64).epsilon(1e-15));
    CHECK(light_value(lobe(n, 0.5), down) == 0.0);
    CHECK(light_value(lobe(n, 3.0), n) == 1.0);
    // Disk: closed; o.l = cos(radius) exactly on the edge (l = n makes o.l = o.z exact).
    const double r = 0.3;
    CHECK(light_value(disk(n, r), {std::sin(r), 0, std::cos(r)}) == 1.0);
    CHECK(light_value(disk(n, r), {std::sin(r), 0, std::nextafter(std::cos(r), 0.0)}) == 0.0);
    CHECK(light_value(disk(n, r), n) == 1.0);
    CHECK(light_value(disk(n, r), -1.0 * n) == 0.0);
    CHECK(light_value(Light{}, down) == 1.0);
    // reflected_radiance: the uniform light ignores l; 0 for a view below the horizon, NaN for a
    // light outside the domain.
    const Params p = params(Method::caps, 0.3, 0.3, 30.0);
    Light uniform_zero_l;
    uniform_zero_l.l = {0.0, 0.0, 0.0};
    CHECK(reflected_radiance(p, uniform_zero_l) == albedo(p));
    CHECK(reflected_radiance({0.3, 0.3, down}, lobe(n, 1.0)) == 0.0);
    CHECK(std::isnan(reflected_radiance(p, lobe(n, -1.0))));
    CHECK(std::isnan(reflected_radiance(p, disk(n, 0.0))));
    CHECK(std::isnan(reflected_radiance(p, disk(n, 2.0))));
    CHECK(std::isnan(reflected_radiance(p, lobe({0, 0, 2}, 1.0))));
    // A disk entirely below the horizon reflects nothing; one pointing at the peak reflects the most.
    CHECK(reflected_radiance(p, disk(normalize({0.1, 0.2, -1.0}), 0.5)) == 0.0);
    CHECK(reflected_radiance(p, disk(mirror(30.0), 0.1)) > reflected_radiance(p, disk(normalize({0.5, 0.5, 0.7}), 0.1)));
}
