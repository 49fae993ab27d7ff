// test_dielectric_albedo.cpp - the single-scattering white furnace of the rough dielectric: the
// integral over normals against one over directions (bins of dielectric_cos), energy below 1 and the
// smooth interface's Fresnel split in the limit alpha -> 0, no reflection as eta -> 1, radiance
// transport, and the Monte Carlo means of the sampled weights per lobe (with the controls that a
// transmittance whose Jacobian lacks eta'^2 is rejected).
#include <doctest/doctest.h>

#include <string>

#include "ggx_dielectric_support.hpp"
#include "ref_test_helpers.hpp"

using namespace reftest;

namespace {

// The lobes' sums over o of dielectric_cos, by the bins of ggx_bin_mass over the whole sphere.
DielectricAlbedo albedo_over_directions(const Params& p, double eta, bool radiance)
{
    auto f = [&](const Vec3& o) { return dielectric_cos(p.i, o, p.ax, p.ay, eta, radiance); };
    const int nz = 8, nphi = 16;
    const detail::Support support = detail::dielectric_support(Method::caps, p, eta);
    const std::vector<double> bins = detail::bin_masses(f, support, nz, nphi, 1e-9);
    double up = 0.0, down = 0.0;
    for (int z = 0; z < nz; ++z)
        for (int k = 0; k < nphi; ++k)
            (z >= nz / 2 ? up : down) += bins[size_t(z) * nphi + k];
    return p.i.z > 0.0 ? DielectricAlbedo{up, down} : DielectricAlbedo{down, up};
}

struct Estimate {
    double mean[2], se[2];  // reflected, transmitted
};

// Means of the sampled weights of each lobe (0 for the other lobe and for invalid samples).
Estimate sampled_albedo(Method method, const Params& p, double eta, bool radiance, size_t count)
{
    const Vec3 n = method == Method::caps_iso ? p.n : Vec3{0.0, 0.0, 1.0};
    double sum[2] = {0.0, 0.0}, sum2[2] = {0.0, 0.0};
    for (size_t k = 0; k < count; ++k) {
        const auto u = uniforms(11, k);
        const Sample s = dielectric_sample(method, p, eta, radiance, u[0], u[1], lobe_uniform_philox(11, k));
        const int lobe = dot(s.o, n) * dot(p.i, n) > 0.0 ? 0 : 1;
        sum[lobe] += s.weight;
        sum2[lobe] += s.weight * s.weight;
    }
    Estimate e{};
    for (int l = 0; l < 2; ++l) {
        e.mean[l] = sum[l] / count;
        e.se[l] = std::sqrt(std::max(0.0, sum2[l] / count - e.mean[l] * e.mean[l]) / (count - 1));
    }
    return e;
}

}  // namespace

TEST_CASE("dielectric albedo: over normals = over directions (1e-9), anisotropic and from below")
{
    struct Case {
        double ax, ay, theta, eta;
    };
    double worst = 0.0;
    for (const Case& c : std::vector<Case>{{0.05, 0.05, 0.0, 2.4},
                                           {0.05, 0.05, 80.0, 1.0 / 1.5},
                                           {0.3, 0.1, 120.0, 2.4},
                                           {0.3, 0.1, 45.0, 1.05},
                                           {0.3, 0.1, 80.0, 1.0 / 1.5},
                                           {1.5, 1.5, 120.0, 1.05},
                                           {1.5, 0.7, 60.0, 1.5}}) {
        const Params p = params(Method::caps, c.ax, c.ay, c.theta);
        const DielectricAlbedo a = dielectric_albedo(p, c.eta, false), b = albedo_over_directions(p, c.eta, false);
        CAPTURE(c.ax);
        CAPTURE(c.ay);
        CAPTURE(c.theta);
        CAPTURE(c.eta);
        CHECK(a.reflectance == doctest::Approx(b.reflectance).epsilon(1e-9));
        CHECK(a.transmittance == doctest::Approx(b.transmittance).epsilon(1e-9));
        worst = std::max({worst, std::fabs(a.reflectance / b.reflectance - 1.0),
                          std::fabs(a.transmittance / b.transmittance - 1.0)});
    }
    MESSAGE("worst relative difference " << worst);
}

TEST_CASE("dielectric albedo: below 1 in importance transport, the smooth interface's split as alpha -> 0")
{
    for (double eta : {1.5, 1.0 / 1.5, 2.4})
        for (double theta : {0.0, 45.0, 80.0, 150.0}) {
            CAPTURE(eta);
            CAPTURE(theta);
            for (double alpha : {0.05, 1.5}) {
                const Params p = params(Method::caps, alpha, 0.7 * alpha, theta);
                const DielectricAlbedo a = dielectric_albedo(p, eta, false);
                CHECK(a.reflectance > 0.0);
                CHECK(a.transmittance >= 0.0);
                CHECK(a.reflectance + a.transmittance < 1.0);
            }
            const Params p = params(Method::caps, 1e-3, 1e-3, theta);
            const DielectricAlbedo smooth = dielectric_albedo(p, eta, false);
            const double F = fresnel_dielectric(p.i.z, eta);  // the other side when iz < 0
            CHECK(smooth.reflectance == doctest::Approx(F).epsilon(1e-4));
            CHECK(std::fabs(smooth.transmittance - (1.0 - F)) < 1e-4);
            const DielectricAlbedo a = dielectric_albedo(params(Method::caps, 0.01, 0.01, theta), eta, false);
            CHECK(a.reflectance + a.transmittance > 1.0 - 3e-3);
        }
}

TEST_CASE("dielectric albedo: the reflectance vanishes as eta -> 1; radiance transport divides T by eta'^2")
{
    for (double theta : {0.0, 80.0, 120.0}) {
        const Params p = params(Method::caps, 0.3, 0.3, theta);
        double previous = 1.0;
        for (double eta : {1.5, 1.1, 1.01, 1.001}) {
            const double r = dielectric_albedo(p, eta, false).reflectance;
            CHECK(r < previous);
            previous = r;
        }
        CHECK(previous < 1e-4);
        const double eta = 1.5, side_eta = theta < 90.0 ? eta : 1.0 / eta;
        const DielectricAlbedo importance = dielectric_albedo(p, eta, false);
        const DielectricAlbedo radiance = dielectric_albedo(p, eta, true);
        CHECK(radiance.reflectance == doctest::Approx(importance.reflectance).epsilon(1e-12));
        const double expected = importance.transmittance / (side_eta * side_eta);
        CHECK(radiance.transmittance == doctest::Approx(expected).epsilon(1e-12));
    }
}

TEST_CASE("dielectric albedo = the sampled weights' means per lobe (5 standard errors); eta'^2 left out is rejected")
{
    struct Case {
        Method method;
        Params p;
        double eta;
        bool radiance;
    };
    const std::vector<Case> cases = {{Method::ndf, params(Method::ndf, 0.3, 0.3, 45.0), 1.5, false},
                                     {Method::caps, params(Method::caps, 0.5, 0.2, 120.0), 1.5, true},
                                     {Method::heitz2017, params(Method::heitz2017, 0.2, 0.2, 70.0), 1.05, false},
                                     {Method::heitz, params(Method::heitz, 0.8, 0.8, 30.0), 1.0 / 1.5, true},
                                     {Method::caps_iso, rotated(0.4, 60.0, normalize({0.3, -0.5, 0.8})), 2.4, false}};
    for (const Case& c : cases) {
        CAPTURE(std::string(method_name(c.method)));
        const DielectricAlbedo exact = dielectric_albedo(c.p, c.eta, c.radiance);
        const Estimate mc = sampled_albedo(c.method, c.p, c.eta, c.radiance, 200000);
        CAPTURE(exact.reflectance);
        CAPTURE(exact.transmittance);
        CAPTURE(mc.mean[0]);
        CAPTURE(mc.mean[1]);
        CHECK(std::fabs(mc.mean[0] - exact.reflectance) < 5.0 * mc.se[0]);
        CHECK(std::fabs(mc.mean[1] - exact.transmittance) < 5.0 * mc.se[1]);
        // The Jacobian d w_m / d w_o without its eta'^2 makes the transmittance eta'^2 times larger.
        const double side_eta = dot(c.p.i, c.p.n) > 0.0 ? c.eta : 1.0 / c.eta;
        CHECK(std::fabs(mc.mean[1] - exact.transmittance * side_eta * side_eta) > 5.0 * mc.se[1]);
    }
}
