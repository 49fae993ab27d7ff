// test_dielectric_sample.cpp - the rough dielectric's samples: unit directions on the lobe's side, the
// density recomputed from (i, o) and the weight f |o.n| / pdf_o that the sample carries, the lobe chosen
// with probability F, views from below as mirrored views from above with 1/eta, invalid normals, and
// bounded's and a bad index's fallback.
#include <doctest/doctest.h>

#include <string>

#include "ref_test_helpers.hpp"

using namespace reftest;

namespace {

const std::vector<double> etas = {1.5, 1.0 / 1.5, 1.05, 2.4};
const std::vector<Method> dielectric_methods = {Method::ndf, Method::heitz, Method::heitz2017, Method::caps,
                                                Method::caps_iso};

struct Counts {
    int valid = 0, reflected = 0, transmitted = 0;
};

// A valid sample: unit o on the lobe's side, pdf_o and weight as recomputed from (i, o); i and o in
// tangent space (n = z) for dielectric_cos.
void check_valid(Method method, const Params& p, double eta, const Sample& s, Counts& counts)
{
    const Vec3 n = method == Method::caps_iso ? p.n : Vec3{0.0, 0.0, 1.0};
    const bool reflected = dot(s.o, n) * dot(p.i, n) > 0.0;
    ++counts.valid;
    ++(reflected ? counts.reflected : counts.transmitted);
    CHECK(length(s.o) == doctest::Approx(1.0).epsilon(1e-13));
    CHECK(length(s.m) == doctest::Approx(1.0).epsilon(1e-13));
    CHECK(dot(s.m, n) * dot(p.i, n) >= 0.0);  // m faces the view's side
    CHECK(close_rel(s.pdf_o, dielectric_pdf_o(method, p, eta, s.o), 1e-9));
    const double f = dielectric_cos(p.i, s.o, p.ax, p.ay, eta, false);
    CHECK(close_rel(s.weight, f / s.pdf_o, 1e-9));
}

void check_grid(Method method, const Params& p, double eta, Counts& counts)
{
    for (double u1 : {0.05, 0.3, 0.55, 0.8, 0.97})
        for (double u2 : {0.1, 0.35, 0.6, 0.9})
            for (double u3 : {0.02, 0.5, 0.98}) {
                CAPTURE(u1);
                CAPTURE(u2);
                CAPTURE(u3);
                const Sample s = dielectric_sample(method, p, eta, false, u1, u2, u3);
                CHECK(std::isfinite(s.pdf_o));
                CHECK(std::isfinite(s.weight));
                if (s.pdf_o > 0.0)
                    check_valid(method, p, eta, s, counts);
                else
                    CHECK(s.weight == 0.0);
            }
}

}  // namespace

TEST_CASE("valid dielectric samples carry the density recomputed from (i, o) and weight = f |o.n| / pdf_o")
{
    Counts counts;
    for (Method method : dielectric_methods)
        for (auto [ax, ay] : std::vector<std::pair<double, double>>{{0.05, 0.05}, {0.3, 0.1}, {1.0, 1.0}, {1.6, 0.7}})
            for (double theta : {0.0, 45.0, 80.0, 120.0, 170.0})
                for (double eta : etas) {
                    CAPTURE(std::string(method_name(method)));
                    CAPTURE(ax);
                    CAPTURE(ay);
                    CAPTURE(theta);
                    CAPTURE(eta);
                    check_grid(method, params(method, ax, ay, theta), eta, counts);
                }
    MESSAGE(counts.valid << " valid samples: " << counts.reflected << " reflected, " << counts.transmitted
                         << " transmitted");
    CHECK(counts.reflected > 1000);
    CHECK(counts.transmitted > 1000);
}

TEST_CASE("radiance transport divides a transmission's weight by eta'^2 and leaves reflections alone")
{
    for (double theta : {30.0, 130.0})
        for (double eta : etas) {
            const Params p = params(Method::caps, 0.4, 0.4, theta);
            const double side_eta = theta < 90.0 ? eta : 1.0 / eta;
            for (double u3 : {0.01, 0.99}) {
                const Sample a = dielectric_sample(Method::caps, p, eta, false, 0.4, 0.6, u3);
                const Sample b = dielectric_sample(Method::caps, p, eta, true, 0.4, 0.6, u3);
                const bool transmitted = a.o.z * p.i.z < 0.0;
                CHECK(b.pdf_o == a.pdf_o);
                CHECK(b.weight == doctest::Approx(transmitted ? a.weight / (side_eta * side_eta) : a.weight));
                if (a.pdf_o > 0.0)
                    CHECK(close_rel(b.weight, dielectric_cos(p.i, b.o, 0.4, 0.4, eta, true) / b.pdf_o, 1e-9));
            }
        }
}

TEST_CASE("u3 below F(i.m) reflects, above it refracts; pdf_o carries F or 1 - F")
{
    for (Method method : dielectric_methods)
        for (double eta : etas) {
            CAPTURE(std::string(method_name(method)));
            CAPTURE(eta);
            const Params p = params(method, 0.3, 0.3, 20.0);  // i.m > 0.8: no total internal reflection at 1/1.5
            const Sample conductor = sample(method, p, 0.3, 0.6);
            const double F = fresnel_dielectric(dot(p.i, conductor.m), eta);
            REQUIRE(F < 0.5);
            const Sample r = dielectric_sample(method, p, eta, false, 0.3, 0.6, F * (1.0 - 1e-9));
            const Sample t = dielectric_sample(method, p, eta, false, 0.3, 0.6, F * (1.0 + 1e-9));
            CHECK(length(r.o - conductor.o) < 1e-15);
            CHECK(r.pdf_o == doctest::Approx(F * conductor.pdf_o).epsilon(1e-14));
            CHECK(r.weight == conductor.weight);
            CHECK(t.o.z < 0.0);
            CHECK(dot(t.o, t.m) < 0.0);
            CHECK(t.pdf_m == conductor.pdf_m);
            // Snell's law: the tangential parts of i and eta o about m are opposite.
            const Vec3 it = p.i - dot(p.i, t.m) * t.m, ot = t.o - dot(t.o, t.m) * t.m;
            CHECK(length(it + eta * ot) < 1e-14);
        }
}

TEST_CASE("a view below is the mirrored view above with 1/eta, its m and o mirrored back")
{
    auto mirror = [](const Vec3& v) { return Vec3{v.x, v.y, -v.z}; };
    for (Method method : {Method::ndf, Method::heitz, Method::heitz2017, Method::caps})
        for (double eta : etas) {
            Params below = params(method, 0.5, 0.2, 125.0), above = below;
            above.i = mirror(below.i);
            for (double u3 : {0.01, 0.6, 0.99}) {
                const Sample b = dielectric_sample(method, below, eta, true, 0.7, 0.2, u3);
                const Sample a = dielectric_sample(method, above, 1.0 / eta, true, 0.7, 0.2, u3);
                CHECK(length(b.m - mirror(a.m)) < 1e-15);
                CHECK(length(b.o - mirror(a.o)) < 1e-15);
                CHECK(b.pdf_o == doctest::Approx(a.pdf_o).epsilon(1e-14));
                CHECK(b.weight == doctest::Approx(a.weight).epsilon(1e-14));
            }
            CHECK(dielectric_pdf_o(method, below, eta, normalize({0.3, 0.1, 0.5})) ==
                  doctest::Approx(dielectric_pdf_o(method, above, 1.0 / eta, normalize({0.3, 0.1, -0.5}))));
        }
}

TEST_CASE("caps-iso about a rotated normal is caps-iso about z, rotated")
{
    const Vec3 n = normalize({0.3, -0.5, 0.8});
    const Rotation R = rotation_to(n);
    for (double theta : {35.0, 120.0})
        for (double eta : etas) {
            const Params local = params(Method::caps_iso, 0.4, 0.4, theta);
            const Params world{0.4, 0.4, R.apply(local.i), n};
            for (double u3 : {0.01, 0.99}) {
                const Sample s = dielectric_sample(Method::caps_iso, world, eta, false, 0.35, 0.8, u3);
                REQUIRE(s.pdf_o > 0.0);
                const Vec3 o = R.inverse(s.o);
                CHECK(close_rel(s.pdf_o, dielectric_pdf_o(Method::caps_iso, local, eta, o), 1e-9));
                CHECK(close_rel(s.weight, dielectric_cos(local.i, o, 0.4, 0.4, eta, false) / s.pdf_o, 1e-9));
            }
        }
}

TEST_CASE("NDF normals facing away from the view give invalid samples")
{
    const Params p = params(Method::ndf, 0.8, 0.8, 85.0);
    int facing_away = 0;
    for (double u1 = 0.05; u1 < 1.0; u1 += 0.1)
        for (double u2 = 0.05; u2 < 1.0; u2 += 0.1) {
            const Sample s = dielectric_sample(Method::ndf, p, 1.5, false, u1, u2, 0.5);
            if (dot(p.i, s.m) <= 0.0) {
                ++facing_away;
                CHECK(s.pdf_o == 0.0);
                CHECK(s.weight == 0.0);
                CHECK(s.pdf_m > 0.0);
            }
        }
    CHECK(facing_away > 5);
}

TEST_CASE("bounded and an index of 1 give the fallback; o crosses near -i as eta nears 1")
{
    const Params p = params(Method::caps, 0.3, 0.3, 50.0);
    for (double eta : {1.0, 0.0, -1.5}) {
        const Sample s = dielectric_sample(Method::caps, p, eta, false, 0.3, 0.3, 0.9);
        CHECK(s.pdf_o == 0.0);
        CHECK(s.o.z == 1.0);
    }
    const Sample b = dielectric_sample(Method::bounded, p, 1.5, false, 0.3, 0.3, 0.9);
    CHECK(b.pdf_o == 0.0);
    CHECK(b.pdf_m == 0.0);
    CHECK(b.m.z == 1.0);
    CHECK(dielectric_pdf_o(Method::bounded, p, 1.5, {0.0, 0.0, -1.0}) == 0.0);
    const Sample t = dielectric_sample(Method::caps, p, 1.0 + 1e-6, false, 0.3, 0.3, 0.9);
    CHECK(length(t.o + p.i) < 1e-5);
    CHECK(dielectric_pdf_o(Method::caps, p, 1.5, {1.0, 0.0, 0.0}) == 0.0);  // on the surface
}
