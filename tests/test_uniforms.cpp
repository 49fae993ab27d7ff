// test_uniforms.cpp - the device Philox4x32-10 against Random123's known
// answers, and device uniforms identical to the host's (Random123) for the
// same (seed, index).  The test kernel includes the public device header
// ggx_philox.h the way a user kernel would.
#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "device_fixture.hpp"

namespace {

const char* test_kernels = R"CL(
__kernel void philox_words(__global const uint* in, __global uint* out)
{
    uint g = get_global_id(0);
    uint c0 = in[6 * g], c1 = in[6 * g + 1], c2 = in[6 * g + 2], c3 = in[6 * g + 3];
    ggx_philox4x32_10(&c0, &c1, &c2, &c3, in[6 * g + 4], in[6 * g + 5]);
    out[4 * g] = c0; out[4 * g + 1] = c1; out[4 * g + 2] = c2; out[4 * g + 3] = c3;
}
__kernel void uniforms(ulong seed, ulong first, __global float* u)
{
    uint g = get_global_id(0);
    float u1, u2;
    ggx_uniforms(seed, first + g, &u1, &u2);
    u[2 * g] = u1; u[2 * g + 1] = u2;
}
)CL";

cl::Program test_program()
{
    static cl::Program program = [] {
        cl::Program p(ggxtest::sampler().context(), ggxcl::kernel_source("ggx_philox.h") + test_kernels);
        p.build({ggxtest::sampler().device()});
        return p;
    }();
    return program;
}

std::vector<std::uint32_t> device_philox(const std::vector<std::uint32_t>& cases)
{
    auto& s = ggxtest::sampler();
    std::size_t n = cases.size() / 6;
    cl::Buffer in(s.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, cases.size() * 4,
                  const_cast<std::uint32_t*>(cases.data()));
    cl::Buffer out(s.context(), CL_MEM_WRITE_ONLY, n * 16);
    cl::Kernel k(test_program(), "philox_words");
    k.setArg(0, in);
    k.setArg(1, out);
    s.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<std::uint32_t> words(4 * n);
    s.queue().enqueueReadBuffer(out, CL_TRUE, 0, n * 16, words.data());
    return words;
}

std::vector<float> device_uniforms(std::uint64_t seed, std::uint64_t first, std::size_t n)
{
    auto& s = ggxtest::sampler();
    cl::Buffer out(s.context(), CL_MEM_WRITE_ONLY, n * 8);
    cl::Kernel k(test_program(), "uniforms");
    k.setArg(0, cl_ulong(seed));
    k.setArg(1, cl_ulong(first));
    k.setArg(2, out);
    s.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<float> u(2 * n);
    s.queue().enqueueReadBuffer(out, CL_TRUE, 0, n * 8, u.data());
    return u;
}

} // namespace

TEST_CASE("device Philox4x32-10 reproduces Random123's known answers")
{
    // Random123 kat_vectors: philox4x32 10 rounds (counter, key) -> output.
    std::vector<std::uint32_t> cases = {
        0, 0, 0, 0, 0, 0,
        0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff,
        0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344, 0xa4093822, 0x299f31d0};
    std::vector<std::uint32_t> expected = {0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8,
                                           0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd,
                                           0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1};
    CHECK(device_philox(cases) == expected);
}

TEST_CASE("device and host draw identical words and uniforms for the same (seed, index)")
{
    const std::uint64_t seeds[] = {0, 1, 0x0123456789abcdefull, ~0ull};
    const std::uint64_t firsts[] = {0, (1ull << 32) - 100, ~0ull - 5000};
    for (std::uint64_t seed : seeds) {
        for (std::uint64_t first : firsts) {
            CAPTURE(seed);
            CAPTURE(first);
            const std::size_t n = 4096;
            std::vector<float> u = device_uniforms(seed, first, n);
            std::size_t mismatches = 0;
            for (std::size_t j = 0; j < n; ++j) {
                std::array<double, 2> host = ggxref::uniforms(seed, first + j);
                mismatches += (double(u[2 * j]) != host[0]) + (double(u[2 * j + 1]) != host[1]);
                mismatches += !(u[2 * j] >= 0.0f && u[2 * j] < 1.0f);
            }
            CHECK(mismatches == 0);
        }
    }
    // The raw words of the host reference equal the device's for a sample counter.
    std::uint64_t seed = 0xfeedfacecafebeefull, index = 0x1122334455667788ull;
    std::array<std::uint32_t, 4> host = ggxref::philox_words(seed, index);
    std::vector<std::uint32_t> device = device_philox({std::uint32_t(index), std::uint32_t(index >> 32), 0, 0,
                                                       std::uint32_t(seed), std::uint32_t(seed >> 32)});
    CHECK(std::vector<std::uint32_t>(host.begin(), host.end()) == device);
}
