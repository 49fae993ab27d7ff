// test_sobol.cpp - the Owen-scrambled Sobol uniforms (kernels/ggx_sobol.h):
//  - device words are bit-identical to the host reference's independent
//    construction (reference/ggx_sobol.cpp), for several seeds and index
//    ranges, across the 2^32 block boundary, with either bit reversal;
//  - the first 2^m points, from index 0, form a (0, m, 2)-net for m = 1..16
//    and several seeds: every elementary interval of area 2^-m holds exactly
//    one point (so do the unscrambled points); negative control: Philox
//    points do not;
//  - different seeds give different scrambles, and point 0 over 4096 seeds
//    is uniform in each coordinate (chi-square); control: the unscrambled
//    point 0 is rejected.
#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "device_fixture.hpp"

namespace {

const char* sobol_kernel = R"CL(
#include "ggx_sobol.h"
__kernel void sobol_words(ulong seed, ulong first, __global uint* out)
{
    uint g = get_global_id(0);
    ggx_word_pair w = ggx_sobol_words(seed, first + g);
    out[2 * g] = w.w1;
    out[2 * g + 1] = w.w2;
}
)CL";

using Words = std::vector<std::array<std::uint32_t, 2>>;

// With `byte_reversal`, the bit reversal that Oclgrind needs (-DGGX_NO_BITREVERSE=1).
Words device_words(std::uint32_t seed, std::uint64_t first, std::size_t n, bool byte_reversal = false)
{
    auto& s = ggxtest::sampler();
    static cl::Program plain = ggxcl::build_user_program(s.context(), s.device(), sobol_kernel);
    static cl::Program bytes =
        ggxcl::build_user_program(s.context(), s.device(), sobol_kernel, "-DGGX_NO_BITREVERSE=1");
    cl::Program& program = byte_reversal ? bytes : plain;
    cl::Kernel kernel(program, "sobol_words");
    cl::Buffer out(s.context(), CL_MEM_WRITE_ONLY, 2 * n * sizeof(cl_uint));
    kernel.setArg(0, cl_ulong(seed));
    kernel.setArg(1, cl_ulong(first));
    kernel.setArg(2, out);
    s.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(n));
    std::vector<cl_uint> flat(2 * n);
    s.queue().enqueueReadBuffer(out, CL_TRUE, 0, flat.size() * sizeof(cl_uint), flat.data());
    Words w(n);
    for (std::size_t k = 0; k < n; ++k)
        w[k] = {flat[2 * k], flat[2 * k + 1]};
    return w;
}

// Whether the first 2^m points are a (0, m, 2)-net in their top 24 bits (the uniforms' bits):
// for every split j + (m - j) = m, each of the 2^m cells of 2^-j by 2^-(m-j) holds one point.
bool is_net(const Words& w, int m)
{
    const std::size_t n = std::size_t(1) << m;
    for (int j = 0; j <= m; ++j) {
        std::vector<std::uint8_t> seen(n, 0);
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t a = (w[k][0] >> 8) >> (24 - j), b = (w[k][1] >> 8) >> (24 - (m - j));
            if (seen[(std::size_t(a) << (m - j)) | b]++)
                return false;
        }
    }
    return true;
}

} // namespace

TEST_CASE("device Sobol words equal the host reference's, bit for bit")
{
    for (std::uint32_t seed : {0u, 1u, 0xdeadbeefu, 0xffffffffu})
        for (std::uint64_t first : {std::uint64_t(0), (std::uint64_t(1) << 32) - 2048, std::uint64_t(1) << 63}) {
            CAPTURE(seed);
            CAPTURE(first);
            const Words device = device_words(seed, first, 4096), by_bytes = device_words(seed, first, 4096, true);
            std::size_t differ = 0;
            for (std::size_t k = 0; k < device.size(); ++k)
                differ += device[k] != ggxref::sobol_words(seed, first + k) || by_bytes[k] != device[k];
            CHECK(differ == 0);
        }
}

TEST_CASE("the first 2^m points are a (0, m, 2)-net for m = 1..16; Philox points are not")
{
    const int most = 16;
    Words plain(std::size_t(1) << most);
    for (std::size_t k = 0; k < plain.size(); ++k)
        plain[k] = ggxref::sobol_points(std::uint32_t(k));
    for (std::uint32_t seed : {0u, 7u, 123456789u, 0xffffffffu}) {
        CAPTURE(seed);
        const Words device = device_words(seed, 0, std::size_t(1) << most);
        for (int m = 1; m <= most; ++m) {
            CAPTURE(m);
            CHECK(is_net(device, m));
            CHECK(is_net(plain, m));
        }
    }
    Words philox(std::size_t(1) << most);
    for (std::size_t k = 0; k < philox.size(); ++k)
        philox[k] = ggxref::philox_words(7, k);
    int philox_nets = 0;
    for (int m = 2; m <= most; ++m)
        philox_nets += is_net(philox, m);
    CHECK(philox_nets == 0);
}

TEST_CASE("seeds give different scrambles, and point 0 is uniform over seeds")
{
    const Words a = device_words(1, 0, 1024), b = device_words(2, 0, 1024);
    std::size_t same = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
        same += a[k] == b[k];
    CHECK(same == 0);
    const int bins = 64, seeds = 4096;
    const std::vector<double> flat(bins, 1.0 / bins);
    for (int dimension : {0, 1}) {
        CAPTURE(dimension);
        std::vector<std::uint64_t> scrambled(bins, 0), plain(bins, 0);
        for (int seed = 0; seed < seeds; ++seed)
            ++scrambled[ggxref::sobol_words(std::uint32_t(seed), 0)[dimension] >> 26];
        ++plain[ggxref::sobol_points(0)[dimension] >> 26];  // always 0: the control
        plain[0] += seeds - 1;
        CHECK(ggxref::chi_square_gof(scrambled, flat).p_value > 1e-3);
        CHECK(ggxref::chi_square_gof(plain, flat).p_value < 1e-6);
    }
}
