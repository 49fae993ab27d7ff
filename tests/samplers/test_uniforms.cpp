// test_uniforms.cpp - the device Philox2x32-10 against Random123's known
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
    ggx_word_pair c;
    c.w1 = in[3 * g];
    c.w2 = in[3 * g + 1];
    c = ggx_philox2x32_10(c, in[3 * g + 2]);
    out[2 * g] = c.w1; out[2 * g + 1] = c.w2;
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
    std::size_t n = cases.size() / 3;
    cl::Buffer in(s.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, cases.size() * 4,
                  const_cast<std::uint32_t*>(cases.data()));
    cl::Buffer out(s.context(), CL_MEM_WRITE_ONLY, n * 8);
    cl::Kernel k(test_program(), "philox_words");
    k.setArg(0, in);
    k.setArg(1, out);
    s.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<std::uint32_t> words(2 * n);
    s.queue().enqueueReadBuffer(out, CL_TRUE, 0, n * 8, words.data());
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

TEST_CASE("device Philox2x32-10 reproduces Random123's known answers")
{
    // Random123 kat_vectors: philox2x32 10 rounds, (counter, key) -> output.
    std::vector<std::uint32_t> cases = {0, 0, 0, 0xffffffff, 0xffffffff, 0xffffffff, 0x243f6a88, 0x85a308d3, 0x13198a2e};
    std::vector<std::uint32_t> expected = {0xff1dae59, 0x6cd10df2, 0x2c3f628b, 0xab4fd7ad, 0xdd7ce038, 0xf62a4c12};
    CHECK(device_philox(cases) == expected);
}

TEST_CASE("device and host draw identical words and uniforms for the same (seed, index)")
{
    const std::uint64_t seeds[] = {0, 1, 0x89abcdefull, 0xffffffffull};
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
    std::uint32_t seed = 0xcafebeefu;
    std::uint64_t index = 0x1122334455667788ull;
    std::array<std::uint32_t, 2> host = ggxref::philox_words(seed, index);
    std::vector<std::uint32_t> device = device_philox({std::uint32_t(index), std::uint32_t(index >> 32), seed});
    CHECK(std::vector<std::uint32_t>(host.begin(), host.end()) == device);
}
