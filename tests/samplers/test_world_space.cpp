// test_world_space.cpp - world-space sampling (SampleParams::world_space):
// every method takes a world-space normal and view and returns world-space m
// and o.  Device samples match the reference's (ggxref::sample_world: the
// Duff et al. basis for the tangent-space methods, none for caps-iso) sample
// by sample with the per-sample tolerances, for uniform and per-sample
// normals and views; the world-space pdf recomputes the returned one; a
// reference with another basis is rejected (negative control).
// Views exactly along n are left out of the sample-by-sample comparison: there
// the view's float-rounded tangential part (~1e-8, any direction) fixes heitz's
// basis around the view, so float and double turn the sample by different
// azimuths (same distribution; docs/STABILITY.md territory).
// Angle bound in world space: 5e-5 rad for 99.9% (2e-5 in tangent space):
// the transform into the basis rounds the view, and heitz's tangent, the
// normalized tangential part of the stretched view, turns with that rounding
// (measured 2.1e-5 at theta 10, alpha 0.05).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "ggx_world.hpp"
#include "sample_compare.hpp"

namespace {

using ggxref::Method;
using ggxref::Vec3;

constexpr std::uint64_t seed = 4242;
constexpr std::uint64_t samples_per_config = 1024;
constexpr ggxtest::ErrorBound world_angle_bound{"angle of m and o (rad)", 5e-5, 2e-3};

Vec3 as_double(const ggxcl::Vec3& v)
{
    return {v.x, v.y, v.z};
}

ggxcl::Vec3 as_float(const Vec3& v)
{
    return {float(v.x), float(v.y), float(v.z)};
}

// A unit view at `theta` degrees from n, turned about n by `phi` (built without the Duff basis).
Vec3 view_about(const Vec3& n, double theta, double phi)
{
    const double rad = 3.14159265358979323846 / 180.0;
    Vec3 t = ggxref::any_perpendicular(n), b = ggxref::cross(n, t);
    Vec3 side = std::cos(phi * rad) * t + std::sin(phi * rad) * b;
    return ggxref::normalize(std::cos(theta * rad) * n + std::sin(theta * rad) * side);
}

std::vector<Vec3> normals_for(Method method)
{
    std::vector<Vec3> normals = {{0, 0, 1}, {1, 0, 0}, ggxref::normalize({0.3, -0.5, 0.6}),
                                 ggxref::normalize({-0.2, 0.1, -0.97})};
    if (method != Method::caps_iso)  // caps-iso is singular at n = -z (docs/STABILITY.md)
        normals.push_back({0, 0, -1});
    return normals;
}

// The device's parameters and the reference's, on the same float-rounded unit vectors.
struct WorldConfig {
    ggxcl::SampleParams device;
    ggxref::Params reference;
};

WorldConfig world_config(Method method, double alpha, const Vec3& n, const Vec3& i, ggxcl::Precision precision)
{
    ggxcl::SampleParams p;
    p.method = ggxtest::to_library(method);
    p.alpha_x = p.alpha_y = float(alpha);
    p.view = as_float(i);
    p.normal = as_float(n);
    p.precision = precision;
    p.world_space = true;
    p = ggxcl::normalized(p);
    return {p, {p.alpha_x, p.alpha_y, as_double(p.view), as_double(p.normal)}};
}

void check_uniform_world(Method method, ggxcl::Precision precision)
{
    ggxtest::SampleErrors errors;
    for (const Vec3& n : normals_for(method))
        for (double alpha : {0.05, 0.3, 1.0})
            for (double theta : {10.0, 40.0, 80.0}) {
                WorldConfig c = world_config(method, alpha, n, view_about(n, theta, 30.0), precision);
                ggxcl::SampleSet d =
                    ggxtest::sampler().generate(c.device, {seed, 0, samples_per_config}, ggxcl::FieldSet::all());
                auto reference = [&](std::size_t, double u1, double u2) {
                    return ggxref::sample_world(method, c.reference, u1, u2);
                };
                ggxtest::compare_samples(d, seed, reference, method == Method::ndf, ggxtest::describe(c.reference),
                                         errors);
            }
    ggxtest::check_sample_errors(std::string(ggxref::method_name(method)) + " world space " +
                                     std::string(ggxcl::precision_name(precision)),
                                 errors, world_angle_bound);
}

} // namespace

TEST_CASE("world space: every method matches the reference sample by sample")
{
    for (Method method : ggxref::all_methods) {
        CAPTURE(ggxref::method_name(method));
        check_uniform_world(method, ggxcl::Precision::precise);
    }
}

TEST_CASE("world space: per-sample normals and views match the reference")
{
    std::mt19937_64 rng(7);
    std::normal_distribution<double> gauss;
    const std::size_t count = 4096;
    ggxcl::PerSampleInputs inputs;
    std::vector<ggxref::Params> refs;
    for (std::size_t j = 0; j < count; ++j) {
        Vec3 n = ggxref::normalize({gauss(rng), gauss(rng), gauss(rng)});
        if (n.z < -0.999)
            n = {0, 0, 1};
        Vec3 i = view_about(n, 85.0 * std::uniform_real_distribution<double>()(rng), 360.0 * (j % 97) / 97.0);
        WorldConfig c = world_config(Method::caps, 0.4, n, i, ggxcl::Precision::precise);
        inputs.normals.push_back(c.device.normal);
        inputs.views.push_back(c.device.view);
        refs.push_back(c.reference);
    }
    for (Method method : ggxref::all_methods) {
        ggxcl::SampleParams p = world_config(method, 0.4, {0, 0, 1}, {0, 0, 1}, ggxcl::Precision::precise).device;
        ggxcl::SampleSet d = ggxtest::sampler().generate(p, {seed, 0, count}, ggxcl::FieldSet::all(), inputs);
        ggxtest::SampleErrors errors;
        auto reference = [&](std::size_t j, double u1, double u2) {
            return ggxref::sample_world(method, refs[j], u1, u2);
        };
        ggxtest::compare_samples(d, seed, reference, method == Method::ndf, "per-sample", errors);
        ggxtest::check_sample_errors(std::string(ggxref::method_name(method)) + " world, per sample", errors,
                                     world_angle_bound);
    }
}

TEST_CASE("world space: the recomputed pdf of each returned o is its pdf_o")
{
    Vec3 n = ggxref::normalize({0.3, -0.5, 0.6});
    for (Method method : ggxref::all_methods) {
        WorldConfig c = world_config(method, 0.3, n, view_about(n, 50.0, 10.0), ggxcl::Precision::precise);
        ggxcl::SampleSet d = ggxtest::sampler().generate(c.device, {seed, 0, 2048}, ggxcl::FieldSet::all());
        std::vector<ggxcl::Vec3> directions;
        for (std::size_t j = 0; j < d.count; ++j)
            directions.push_back(d.o_at(j));
        std::vector<float> pdf = ggxtest::sampler().pdf(c.device, directions);
        std::vector<double> errors;
        for (std::size_t j = 0; j < d.count; ++j)
            if (method != Method::ndf || std::fabs(ggxref::dot(as_double(d.o_at(j)), as_double(d.m_at(j)))) >= 1e-2)
                errors.push_back(ggxtest::relative_error(pdf[j], d.pdf_o[j]));
        ggxtest::check_errors(ggxref::method_name(method), ggxtest::pdf_bound, errors);
    }
}

TEST_CASE("world space needs one roughness: anisotropic alpha is refused by name")
{
    ggxcl::SampleParams p;
    p.method = ggxcl::Method::heitz;
    p.alpha_x = 0.2f;
    p.alpha_y = 0.5f;
    p.world_space = true;
    CHECK_THROWS_WITH_AS(ggxcl::validate(p), doctest::Contains("alpha"), ggxcl::InvalidArgument);
}

TEST_CASE("negative control: a reference with another tangent basis is rejected")
{
    Vec3 n = ggxref::normalize({0.3, -0.5, 0.6});
    WorldConfig c = world_config(Method::caps, 0.3, n, view_about(n, 40.0, 0.0), ggxcl::Precision::precise);
    ggxcl::SampleSet d = ggxtest::sampler().generate(c.device, {seed, 0, samples_per_config}, ggxcl::FieldSet::all());
    // The same tangent-space sampler, carried by a basis turned by 90 degrees about n
    // (caps measures its azimuth from the tangent; heitz, isotropic, would not notice).
    ggxref::Basis duff = ggxref::duff_basis(c.reference.n);
    ggxref::Basis turned{duff.b, -1.0 * duff.t, duff.n};
    std::size_t far = 0;
    for (std::size_t j = 0; j < d.count; ++j) {
        std::array<double, 2> u = ggxref::uniforms(seed, j);
        ggxref::Params local = c.reference;
        local.i = ggxref::to_local(turned, c.reference.i);
        local.n = {0, 0, 1};
        Vec3 o = ggxref::to_world(turned, ggxref::sample(Method::caps, local, u[0], u[1]).o);
        far += ggxtest::angle_between(as_double(d.o_at(j)), o) > ggxtest::angle_bound.maximum;
    }
    CHECK(far > d.count / 2);
}
