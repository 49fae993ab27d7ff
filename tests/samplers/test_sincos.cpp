// test_sincos.cpp - the sampling angle's sine and cosine (kernels/
// ggx_sincos.h) on the device, against sin(2 pi u) and cos(2 pi u) in double
// (its rounding is 1e-9 of a float ulp), for every u of the generator's 24-bit grid and u = 1: the error
// in ulp of the exact value stays within the bound the header states, with
// fused multiply-adds and without.  A control shows the measure fails the
// plain sinf and cosf of the angle rounded to float (2 pi u loses the
// exact zeros and a few ulp near them).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "device_fixture.hpp"

namespace {

const char* sincos_kernel = R"CL(
__kernel void sincos_grid(__global float* s, __global float* c)
{
    uint k = get_global_id(0);
    ggx_sin_cos turn = ggx_sincos_2pi((float)k * 5.9604644775390625e-8f);
    s[k] = turn.sine;
    c[k] = turn.cosine;
}
)CL";

constexpr std::size_t grid_points = (std::size_t(1) << 24) + 1;  // k 2^-24 for k = 0 .. 2^24

struct Grid {
    std::vector<float> s, c;
};

Grid device_grid(const std::string& options)
{
    auto& sampler = ggxtest::sampler();
    cl::Program program(sampler.context(), ggxcl::kernel_source("ggx_sincos.h") + sincos_kernel);
    program.build({sampler.device()}, options.c_str());
    cl::Buffer s(sampler.context(), CL_MEM_WRITE_ONLY, grid_points * 4), c(sampler.context(), CL_MEM_WRITE_ONLY,
                                                                            grid_points * 4);
    cl::Kernel kernel(program, "sincos_grid");
    kernel.setArg(0, s);
    kernel.setArg(1, c);
    sampler.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(grid_points));
    Grid grid{std::vector<float>(grid_points), std::vector<float>(grid_points)};
    sampler.queue().enqueueReadBuffer(s, CL_TRUE, 0, grid_points * 4, grid.s.data());
    sampler.queue().enqueueReadBuffer(c, CL_TRUE, 0, grid_points * 4, grid.c.data());
    return grid;
}

// |value - exact| in units of the float ulp of exact; an exact zero must be met exactly.
double ulps(float value, double exact, bool exact_zero)
{
    if (exact_zero)
        return value == 0.0f ? 0.0 : 1e30;
    int exponent;
    std::frexp(double(std::fabs(exact)), &exponent);
    return std::fabs(double(value) - exact) / std::ldexp(1.0, exponent - 24);
}

struct MaxError {
    double sine = 0, cosine = 0;
};

// Quarter turns are exact: sine zero at u = 0, 1/2, 1, cosine zero at 1/4, 3/4.
MaxError max_error(const Grid& grid)
{
    const double two_pi = 6.283185307179586476925286766559;
    const std::size_t quarter = std::size_t(1) << 22;
    MaxError worst;
    for (std::size_t k = 0; k < grid_points; ++k) {
        double angle = two_pi * std::ldexp(double(k), -24);
        bool on_quarter = k % quarter == 0, odd_quarter = on_quarter && (k / quarter) % 2 == 1;
        worst.sine = std::max(worst.sine, ulps(grid.s[k], std::sin(angle), on_quarter && !odd_quarter));
        worst.cosine = std::max(worst.cosine, ulps(grid.c[k], std::cos(angle), odd_quarter));
    }
    return worst;
}

} // namespace

TEST_CASE("sincos of 2 pi u: at most 0.86 ulp over the whole 24-bit grid with fma")
{
    MaxError e = max_error(device_grid(""));
    MESSAGE("max error: sine " << e.sine << " ulp, cosine " << e.cosine << " ulp");
    CHECK(e.sine <= 0.86);
    CHECK(e.cosine <= 0.86);
}

TEST_CASE("sincos of 2 pi u: at most 1.6 ulp without fma (GGX_NO_FMA)")
{
    MaxError e = max_error(device_grid("-DGGX_NO_FMA=1"));
    MESSAGE("max error: sine " << e.sine << " ulp, cosine " << e.cosine << " ulp");
    CHECK(e.sine <= 1.6);
    CHECK(e.cosine <= 1.6);
}

TEST_CASE("control: sinf and cosf of the float angle 2 pi u fail the measure")
{
    Grid rounded{std::vector<float>(grid_points), std::vector<float>(grid_points)};
    for (std::size_t k = 0; k < grid_points; ++k) {
        float angle = 6.28318530717958647692f * std::ldexp(float(k), -24);
        rounded.s[k] = std::sin(angle);
        rounded.c[k] = std::cos(angle);
    }
    MaxError e = max_error(rounded);
    MESSAGE("float-angle max error: sine " << e.sine << " ulp, cosine " << e.cosine << " ulp");
    CHECK(e.sine > 2.0);
    CHECK(e.cosine > 2.0);
}
