// test_device_math.cpp - the GGX math of kernels/ggx_math.h, as a user
// kernel includes it, against the double reference on random inputs: D and
// its isotropic form, Lambda (both hemispheres), G1, both G2 forms, the
// projected area (views below the horizon too) and the VNDF.  A control
// shows the comparison tells the two G2 forms apart.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "device_fixture.hpp"

namespace {

using ggxref::Vec3;

// One work-item per case: inputs w, m, i (9 floats) and ax, ay; 9 outputs.
const char* math_kernel = R"CL(
__kernel void math(__global const float* in, __global float* out)
{
    uint g = get_global_id(0);
    __global const float* p = in + 11 * g;
    ggx_vec3 w = ggx_vec3_make(p[0], p[1], p[2]), m = ggx_vec3_make(p[3], p[4], p[5]);
    ggx_vec3 i = ggx_vec3_make(p[6], p[7], p[8]);
    float ax = p[9], ay = p[10];
    __global float* r = out + 9 * g;
    r[0] = ggx_D(m, ax, ay);
    r[1] = ggx_D_iso(m, ax);
    r[2] = ggx_lambda(w, ax, ay);
    r[3] = ggx_G1(i, ax, ay);
    r[4] = ggx_G2(i, w, ax, ay);
    r[5] = ggx_G2_separable(i, w, ax, ay);
    r[6] = ggx_projected_area(i, ax, ay);
    r[7] = ggx_vndf_pdf(m, i, ax, ay);
    r[8] = ggx_vndf_reflection_pdf(m, i, ax, ay);
}
)CL";

struct Case {
    Vec3 w, m, i;
    double ax, ay;
};

Vec3 random_direction(std::mt19937_64& rng, double zmin, double zmax)
{
    std::uniform_real_distribution<double> z(zmin, zmax), phi(0.0, 6.283185307179586);
    double zz = z(rng), s = std::sqrt(1 - zz * zz), a = phi(rng);
    Vec3 v{float(s * std::cos(a)), float(s * std::sin(a)), float(zz)};  // exactly what the device gets
    return v;
}

std::vector<Case> random_cases(std::size_t n)
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> log_alpha(std::log(0.02), std::log(2.0));
    std::vector<Case> cases;
    for (std::size_t k = 0; k < n; ++k) {
        double ax = float(std::exp(log_alpha(rng))), ay = float(std::exp(log_alpha(rng)));
        cases.push_back({random_direction(rng, -0.95, 0.95), random_direction(rng, 0.05, 1.0),
                         random_direction(rng, k % 4 == 0 ? -0.9 : 0.05, 1.0), ax, ay});
    }
    return cases;
}

std::vector<float> device_math(const std::vector<Case>& cases)
{
    std::vector<float> in;
    for (const Case& c : cases)
        for (double v : {c.w.x, c.w.y, c.w.z, c.m.x, c.m.y, c.m.z, c.i.x, c.i.y, c.i.z, c.ax, c.ay})
            in.push_back(float(v));
    return ggxtest::run_user_kernel(math_kernel, "math", in, cases.size(), 9);
}

} // namespace

TEST_CASE("device GGX math equals the reference on random inputs")
{
    std::vector<Case> cases = random_cases(4000);
    std::vector<float> d = device_math(cases);
    std::size_t bad[9] = {}, g2_forms_differ = 0;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const Case& c = cases[k];
        const float* r = &d[9 * k];
        bool above = c.i.z > 0.0;
        bad[0] += !ggxtest::close_to(r[0], ggxref::D(c.m, c.ax, c.ay), 1e-4, 0.0);
        bad[1] += !ggxtest::close_to(r[1], ggxref::D(c.m, c.ax, c.ax), 1e-4, 0.0);
        bad[2] += !ggxtest::close_to(r[2], ggxref::lambda(c.w, c.ax, c.ay), 1e-4, 1e-5);
        bad[3] += !ggxtest::close_to(r[3], ggxref::G1(c.i, c.ax, c.ay), 1e-4, 1e-6);
        bad[4] += !ggxtest::close_to(r[4], ggxref::G2_height_correlated(c.i, c.w, c.ax, c.ay), 1e-4, 1e-6);
        bad[5] += !ggxtest::close_to(r[5], ggxref::G2_separable(c.i, c.w, c.ax, c.ay), 1e-4, 1e-6);
        bad[6] += !ggxtest::close_to(r[6], ggxref::projected_area(c.i, c.ax, c.ay), 1e-4, 0.0);
        bad[7] += !ggxtest::close_to(r[7], ggxref::vndf_pdf(c.m, c.i, c.ax, c.ay), 1e-4, 1e-6);
        // D(m) / (2 (iz + t)) = D(m) / (4 sigma(i)), the density of o given a visible m
        bad[8] += !ggxtest::close_to(r[8], ggxref::D(c.m, c.ax, c.ay) / (4.0 * ggxref::projected_area(c.i, c.ax, c.ay)), 1e-4,
                         1e-6);
        g2_forms_differ += above && c.w.z > 0 && std::fabs(r[4] - r[5]) > 1e-3;
    }
    const char* names[9] = {"D", "D_iso", "lambda", "G1", "G2", "G2_separable", "projected_area", "vndf_pdf",
                            "vndf_reflection_pdf"};
    for (int q = 0; q < 9; ++q) {
        CAPTURE(std::string(names[q]));
        CHECK(bad[q] == 0);
    }
    CHECK(g2_forms_differ > 500);  // control: the comparison distinguishes the two G2 forms
}
