// test_cap_rim.cpp - the caps family where the cap point c nears -v: the
// last uniforms u2 = 1 - j 2^-24 with u1 swept ulp by ulp around the
// azimuth of -v.  There h = c + v cancels, the rounded m turns by ~6e-8/|h|
// and can face away from i (docs/MATH.md "i.m of a cap sample").  A user
// kernel calls ggx_sample_caps, ggx_sample_bounded and ggx_sample_caps_iso
// (both of its forms) on that grid: pdf_m is never negative and always
// finite, and it is 4 max(0, i.m) pdf_o, the VNDF of the m returned (0 where
// m faces away).  Control: the grid reaches the cancellation, where
// 4 (i.m) pdf_o, the form without the max, is negative.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "device_fixture.hpp"

namespace {

constexpr unsigned rows = 64;       // u2 = 1 - j 2^-24, j = 1 .. rows
constexpr unsigned columns = 2049;  // u1 = centre + (d - 1024) 2^-24, d = 0 .. columns - 1

const char* rim_kernel = R"CL(
#include "ggx_samplers.h"
// Sample j of the grid: u2 = 1 - (1 + j % rows) 2^-24 and u1 = u1_centre + (j / rows - columns / 2) 2^-24
// (u1_centre in [1/2, 1), where the step is one ulp).  Writes pdf_m, pdf_o and dot(i, m).
__kernel void rim_samples(int method, float ix, float iy, float iz, float ax, float ay, float u1_centre,
                          uint rows, uint columns, __global float* out)
{
    uint j = get_global_id(0), count = rows * columns;
    float u2 = 1.0f - (float)(1u + j % rows) * 0x1p-24f;
    float u1 = u1_centre + ((float)(j / rows) - (float)(columns / 2u)) * 0x1p-24f;
    ggx_vec3 i = ggx_vec3_make(ix, iy, iz);
    ggx_sample s = ggx_sample_method(method, ggx_vec3_make(0.0f, 0.0f, 1.0f), i, ax, ay, u1, u2);
    out[j] = s.pdf_m;
    out[count + j] = s.pdf_o;
    out[2u * count + j] = ggx_dot(i, s.m);
}
)CL";

struct Case {
    ggxcl::Method method;
    float ax, ay;
    double theta;
    std::string options;  // -DGGX_NORMAL_IS_Z=1: caps-iso's form for n = +z
};

struct RimCounts {
    std::size_t negative = 0, not_finite = 0, facing_away = 0, off_vndf = 0;
};

// The view at theta, azimuth 35 degrees (caps-iso: 215), as the device sees it.
ggxcl::SampleParams device_params(const Case& c)
{
    const double phi = c.method == ggxcl::Method::caps_iso ? 215.0 : 35.0;
    return ggxcl::normalized({c.method, c.ax, c.ay, ggxcl::view_from_angles(c.theta, phi)});
}

// The azimuth of the cap point at -v as a uniform in [1/2, 1): the stretched view's azimuth plus
// pi (caps, bounded); caps-iso turns its cap by pi about n = z, so there it is the view's own.
float rim_u1(const Case& c, const ggxcl::Vec3& i)
{
    const double pi = 3.14159265358979323846;
    double azimuth = std::atan2(double(c.ay) * i.y, double(c.ax) * i.x);
    if (c.method != ggxcl::Method::caps_iso)
        azimuth += pi;
    double u = azimuth / (2.0 * pi);
    u -= std::floor(u);
    REQUIRE(u >= 0.5 + 1e-3);  // the sweep of +-1024 ulps stays within [1/2, 1)
    REQUIRE(u < 1.0 - 1e-3);
    return float(std::round(u * 16777216.0) / 16777216.0);
}

RimCounts run_rim(const Case& c)
{
    ggxcl::Sampler& sampler = ggxtest::sampler();
    const ggxcl::SampleParams p = device_params(c);
    cl::Program program = ggxcl::build_user_program(sampler.context(), sampler.device(), rim_kernel, c.options);
    const std::size_t count = std::size_t(rows) * columns;
    cl::Buffer out(sampler.context(), CL_MEM_WRITE_ONLY, 3 * count * sizeof(float));
    cl::Kernel kernel(program, "rim_samples");
    const float values[] = {p.view.x, p.view.y, p.view.z, c.ax, c.ay, rim_u1(c, p.view)};
    kernel.setArg(0, cl_int(static_cast<int>(c.method)));
    for (int k = 0; k < 6; ++k)
        kernel.setArg(1 + k, values[k]);
    kernel.setArg(7, cl_uint(rows));
    kernel.setArg(8, cl_uint(columns));
    kernel.setArg(9, out);
    sampler.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(count));
    std::vector<float> host(3 * count);
    sampler.queue().enqueueReadBuffer(out, CL_TRUE, 0, host.size() * sizeof(float), host.data());
    RimCounts counts;
    for (std::size_t j = 0; j < count; ++j) {
        const double pdf_m = host[j], pdf_o = host[count + j], im = host[2 * count + j];
        const double vndf = 4.0 * std::max(0.0, im) * pdf_o;
        counts.negative += pdf_m < 0.0;
        counts.not_finite += !std::isfinite(pdf_m);
        counts.facing_away += im < 0.0;
        counts.off_vndf += !(std::fabs(pdf_m - vndf) <= 1e-6 * vndf);
    }
    return counts;
}

std::string label(const Case& c)
{
    return std::string(ggxcl::method_name(c.method)) + " alpha (" + std::to_string(c.ax) + ", " +
           std::to_string(c.ay) + ") theta " + std::to_string(c.theta) + " '" + c.options + "'";
}

} // namespace

TEST_CASE("cap samples with c near -v: pdf_m is 4 max(0, i.m) pdf_o, never negative")
{
    // bounded's cap reaches -v only as k -> 1, at small roughness.
    const Case cases[] = {{ggxcl::Method::caps, 0.5f, 0.5f, 70.0, ""},
                          {ggxcl::Method::caps, 0.3f, 0.8f, 60.0, ""},
                          {ggxcl::Method::caps, 1.5f, 1.5f, 50.0, ""},
                          {ggxcl::Method::caps, 0.05f, 0.02f, 50.0, ""},
                          {ggxcl::Method::bounded, 1e-3f, 1e-3f, 85.0, ""},
                          {ggxcl::Method::bounded, 1e-4f, 3e-4f, 70.0, ""},
                          {ggxcl::Method::caps_iso, 0.5f, 0.5f, 85.0, ""},
                          {ggxcl::Method::caps_iso, 0.5f, 0.5f, 85.0, "-DGGX_NORMAL_IS_Z=1"}};
    std::size_t facing_away = 0;
    for (const Case& c : cases) {
        RimCounts counts = run_rim(c);
        MESSAGE(label(c) << ": " << counts.facing_away << " of " << rows * columns
                         << " samples with i.m < 0 (4 (i.m) pdf_o negative), negative pdf_m " << counts.negative);
        CAPTURE(label(c));
        CHECK(counts.negative == 0);
        CHECK(counts.not_finite == 0);
        CHECK(counts.off_vndf == 0);
        facing_away += counts.facing_away;
    }
    CHECK(facing_away > 0);  // control: the grid reaches the cancellation
}
