// test_half_math.cpp - the GGX math and the samplers built in half precision (GGX_ARITHMETIC 16: C++
// _Float16, -mf16c, -ffp-contract=off, every operation rounded to half) against the double
// reference on the same half inputs: D, Lambda, G1 and both G2 over roughnesses 0.05 to 1 and
// directions where every value is a normal half number, within 2^-7 relative (16 half ulps; Lambda,
// whose (t/|z| - 1)/2 cancels in half as t nears |z|, against 1 + Lambda, what G1 divides by); the
// errors are half-sized, not float-sized (control: the largest is above 1e-4); a D off by 1% in
// alpha fails the same bound (negative control); and D at the pole overflows to Inf where
// 1 / (pi alpha^2) passes 65504, alpha 0.002.  Every method's m, sample by sample, against the
// reference's on the same half view, roughness and uniforms (Philox's, rounded toward zero by
// ggx_uniform_real, which keeps every float below 1 below 1 in half: checked on all 2^24 of them),
// and the sampling angle's sine and cosine in half on every half u in [0, 1).  The CPU's f16 flags
// are printed: a CPU with AVX512-FP16 lowers _Float16 to its own instructions.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "ggx_reference.hpp"
#include "sample_compare.hpp"

namespace ggx_f16 {
#define GGX_ARITHMETIC 16
#include "ggx_philox.h"
#include "ggx_samplers.h"
} // namespace ggx_f16

namespace {

using half = _Float16;
constexpr double bound = 1.0 / 128;  // 2^-7: 16 ulps of a half near 1

struct HalfVec {
    ggx_f16::ggx_vec3 h;  // the half direction the math gets
    ggxref::Vec3 d;       // the same numbers as doubles, for the reference
};

HalfVec half_vec(double x, double y, double z)
{
    const half hx = half(x), hy = half(y), hz = half(z);
    return {ggx_f16::ggx_vec3_make(hx, hy, hz), {double(hx), double(hy), double(hz)}};
}

// Unit directions over the sphere, each rounded to half, |z| >= 0.05 (Lambda's 1/|z| stays normal).
std::vector<HalfVec> directions(int count)
{
    std::mt19937_64 random(20261207);
    std::normal_distribution<double> normal;
    std::vector<HalfVec> out;
    while (int(out.size()) < count) {
        double x = normal(random), y = normal(random), z = normal(random);
        const double length = std::sqrt(x * x + y * y + z * z);
        x /= length, y /= length, z /= length;
        if (std::fabs(z) >= 0.05)
            out.push_back(half_vec(x, y, z));
    }
    return out;
}

// The largest relative error of one function over the grid, counting only values that are normal
// half numbers (>= 2^-14, <= 65504), and how many were counted.
struct Worst {
    double error = 0;
    int counted = 0;
    void add(double got, double want, double scale)
    {
        if (!(std::fabs(want) >= 6.103515625e-05 && std::fabs(want) <= 65504.0))
            return;
        error = std::max(error, std::fabs(got - want) / scale);
        ++counted;
    }
    void add(double got, double want) { add(got, want, std::fabs(want)); }
};

std::string f16_flags()
{
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, flags;
    while (std::getline(cpuinfo, line))
        if (line.rfind("flags", 0) == 0) {
            for (const char* flag : {" f16c", " avx512fp16", " avx512_fp16"})
                if (line.find(std::string(flag) + " ") != std::string::npos)
                    flags += flag;
            break;
        }
    return flags.empty() ? " (none)" : flags;
}

} // namespace

TEST_CASE("the GGX math in half precision agrees with the double reference within 16 half ulps")
{
    MESSAGE("CPU f16 flags:" << f16_flags());
    const std::vector<HalfVec> dirs = directions(4000);
    const double alphas[][2] = {{0.05, 0.05}, {0.1, 0.1}, {0.3, 0.3}, {0.6, 0.6}, {1.0, 1.0}, {0.1, 0.5}};
    Worst D, lambda, G1, G2, G2_separable;
    for (const auto& a : alphas) {
        const half ax = half(a[0]), ay = half(a[1]);
        const double dx = double(ax), dy = double(ay);
        for (std::size_t k = 0; k < dirs.size(); ++k) {
            const HalfVec& w = dirs[k];
            const HalfVec& v = dirs[(k * 7 + 3) % dirs.size()];
            if (w.d.z > 0)
                D.add(double(ggx_f16::ggx_D(w.h, ax, ay)), ggxref::D(w.d, dx, dy));
            const double exact_lambda = ggxref::lambda(w.d, dx, dy);
            lambda.add(double(ggx_f16::ggx_lambda(w.h, ax, ay)), exact_lambda, 1 + std::fabs(exact_lambda));
            G1.add(double(ggx_f16::ggx_G1(w.h, ax, ay)), ggxref::G1(w.d, dx, dy));
            G2.add(double(ggx_f16::ggx_G2(w.h, v.h, ax, ay)), ggxref::G2_height_correlated(w.d, v.d, dx, dy));
            G2_separable.add(double(ggx_f16::ggx_G2_separable(w.h, v.h, ax, ay)),
                             ggxref::G2_separable(w.d, v.d, dx, dy));
        }
    }
    const Worst* all[] = {&D, &lambda, &G1, &G2, &G2_separable};
    const std::string names[] = {"D", "lambda", "G1", "G2", "G2_separable"};
    double largest = 0;
    for (int f = 0; f < 5; ++f) {
        CAPTURE(names[f]);
        MESSAGE(names[f] << ": largest error " << all[f]->error << " over " << all[f]->counted << " values");
        CHECK(all[f]->counted > 3000);
        CHECK(all[f]->error <= bound);
        largest = std::max(largest, all[f]->error);
    }
    CHECK(largest > 1e-4);  // control: half arithmetic, not float (float's would be about 1e-7)
}

TEST_CASE("the bound rejects a D whose alpha is 1% off (negative control)")
{
    Worst off;
    for (const HalfVec& w : directions(2000))
        if (w.d.z > 0)
            off.add(double(ggx_f16::ggx_D(w.h, half(0.303), half(0.303))), ggxref::D(w.d, double(half(0.3)),
                                                                                       double(half(0.3))));
    CHECK(off.counted > 500);
    CHECK(off.error > bound);
}

TEST_CASE("D at the pole overflows half where 1 / (pi alpha^2) passes 65504")
{
    const HalfVec pole = half_vec(0, 0, 1);
    CHECK(std::isfinite(double(ggx_f16::ggx_D(pole.h, half(0.003), half(0.003)))));  // 35 368
    CHECK(std::isinf(double(ggx_f16::ggx_D(pole.h, half(0.002), half(0.002)))));     // 79 577 in double
    CHECK(ggxref::D(pole.d, double(half(0.002)), double(half(0.002))) > 65504.0);
}

namespace {

// The angles between the half build's m and the reference's over views 0-80 degrees and alphas 0.1-1,
// on Philox's uniforms made half by ggx_uniform_real; `swap` feeds the half build (u2, u1): a wrong
// sample for the control.
std::vector<double> half_angles(ggxref::Method method, bool swap)
{
    std::uint64_t index = 0;
    const double alphas[][2] = {{0.1, 0.1}, {0.3, 0.3}, {1.0, 1.0}, {0.1, 0.5}};
    std::vector<double> angles;
    for (const auto& a : alphas) {
        if (method == ggxref::Method::caps_iso && a[0] != a[1])
            continue;  // isotropic alpha only
        for (double theta : {0.0, 30.0, 60.0, 80.0}) {
            const double t = theta * M_PI / 180, p = 20 * M_PI / 180;
            const HalfVec view = half_vec(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
            const half ax = half(a[0]), ay = half(a[1]);
            const ggxref::Params params{double(ax), double(ay), view.d};
            for (int k = 0; k < 2000; ++k) {
                const ggx_f16::ggx_uniform_pair u = ggx_f16::ggx_philox_pair(20261207, index++);
                const half u1 = ggx_f16::ggx_uniform_real(u.u1), u2 = ggx_f16::ggx_uniform_real(u.u2);
                const ggxref::Sample want = ggxref::sample(method, params, double(u1), double(u2));
                const ggx_f16::ggx_sample got = ggx_f16::ggx_sample_method(
                    int(method), ggx_f16::ggx_vec3_make(half(0), half(0), half(1)), view.h, ax, ay, swap ? u2 : u1,
                    swap ? u1 : u2);
                if (!(want.pdf_o > 0))
                    continue;  // the fallback (none on this grid) is the guards' test
                const double angle = ggxtest::angle_between({double(got.m.x), double(got.m.y), double(got.m.z)},
                                                            want.m);
                angles.push_back(std::isnan(angle) ? 10.0 : angle);  // NaN: 10
            }
        }
    }
    std::sort(angles.begin(), angles.end());
    return angles;
}

} // namespace

// Bounds over the measurements (2026-12-07, g++ 12, F16C): p99 4.6e-4 (ndf) to 7.1e-3 rad (heitz), max
// 7.7e-4 (ndf) to 0.20 rad (caps-iso; 0.24 on other uniforms), where a grazing view's visible region
// is thin; no NaN (counted as 10 rad).  Where each method breaks in half is the fp16 stability map's to say.
TEST_CASE("every method samples in half precision close to the reference on the same half inputs")
{
    for (ggxref::Method method : ggxref::all_methods) {
        const std::vector<double> angles = half_angles(method, false);
        const double p99 = angles[angles.size() * 99 / 100], largest = angles.back();
        const std::string name = ggxref::method_name(method);
        CAPTURE(name);
        MESSAGE(name << ": angle of m, p99 " << p99 << " rad, max " << largest << " over " << angles.size()
                     << " samples");
        CHECK(angles.size() >= 24000);
        CHECK(p99 <= 1e-2);
        CHECK(largest <= 0.5);
    }
    const std::vector<double> swapped = half_angles(ggxref::Method::caps, true);
    CHECK(swapped[swapped.size() * 99 / 100] > 1e-2);  // negative control: the uniforms swapped
}

TEST_CASE("uniforms become half rounded toward zero: every float below 1 stays below 1, at the half below or equal")
{
    int mismatches = 0, rounded_to_one = 0;
    for (std::uint32_t k = 0; k < (1u << 24); ++k) {  // every float k 2^-24 in [0, 1), Philox's grid
        const float u = float(k) * 0x1p-24f;
        const half h = ggx_f16::ggx_uniform_real(u);
        const half up = half(u);  // to nearest: the control
        rounded_to_one += float(up) == 1.0f;
        // Toward zero: h <= u < the next half above h.
        unsigned short bits;
        std::memcpy(&bits, &h, sizeof bits);
        const unsigned short next_bits = (unsigned short)(bits + 1u);
        half next;
        std::memcpy(&next, &next_bits, sizeof next);
        mismatches += !(float(h) <= u && u < float(next) && float(h) < 1.0f);
    }
    CHECK(mismatches == 0);
    CHECK(rounded_to_one == 4096);  // negative control: to nearest, the 2^12 floats from 1 - 2^-12 on become 1.0
}

TEST_CASE("the sampling angle's sine and cosine in half: every half u in [0, 1) within 1.25 x 2^-11")
{
    double worst = 0;  // in units of 2^-11, a half ulp in [0.5, 1)
    int exact_quarters = 0;
    for (unsigned short bits = 0; bits < 0x3C00; ++bits) {  // every half in [0, 1)
        half u;
        std::memcpy(&u, &bits, sizeof u);
        const ggx_f16::ggx_sin_cos got = ggx_f16::ggx_sincos_2pi(u);
        const double angle = 2 * M_PI * double(u);
        worst = std::max({worst, std::fabs(double(got.sine) - std::sin(angle)) * 2048,
                          std::fabs(double(got.cosine) - std::cos(angle)) * 2048});
        if (double(u) * 4 == std::rint(double(u) * 4))
            exact_quarters += std::fabs(double(got.sine)) == std::fabs(std::rint(std::sin(angle))) &&
                              std::fabs(double(got.cosine)) == std::fabs(std::rint(std::cos(angle)));
    }
    MESSAGE("half sincos: largest error " << worst << " x 2^-11");
    CHECK(worst <= 1.25);  // 2.5 half ulps near 1 (measured 1.12: x = f^2 and three fmas, each rounded)
    CHECK(exact_quarters == 4);  // 0, 1/4, 1/2, 3/4: 0 and 1 exactly
    // Negative control: the float form's pi/2 rounded to half, no remainder, misses by more.
    double without_remainder = 0;
    for (unsigned short bits = 0x3000; bits < 0x3400; ++bits) {  // u in [1/8, 1/4): f up to 1/2
        half u;
        std::memcpy(&u, &bits, sizeof u);
        const ggx_f16::ggx_sin_cos got = ggx_f16::ggx_sincos_2pi(u);
        const half f = half(4 * double(u) - std::rint(4 * double(u)));
        const double wrong = double(got.sine) - double(f) * 4.838267949e-04;  // the remainder's share taken out
        without_remainder = std::max(without_remainder, std::fabs(wrong - std::sin(2 * M_PI * double(u))) * 2048);
    }
    CHECK(without_remainder > worst);
}
