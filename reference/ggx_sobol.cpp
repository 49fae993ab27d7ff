// ggx_sobol.cpp - the Owen-scrambled Sobol uniforms of kernels/ggx_sobol.h,
// computed independently of the kernel: the generator matrices as matrices
// over GF(2) (the identity for van der Corput; for Sobol's second dimension
// the Pascal matrix, entry (i, j) = C(j, i) mod 2, odd exactly when the bits
// of i are a subset of those of j, by Lucas' theorem), applied digit by
// digit; the scramble as the same keyed bijection of the reversed digits,
// written in 64-bit arithmetic reduced mod 2^32.
#include "ggx_reference.hpp"

namespace ggxref {

namespace {

constexpr uint64_t mask32 = 0xffffffffull;

// Digit i (i = 0 the most significant, weight 2^-(i+1)) of a 32-bit binary fraction w.
int digit(uint32_t w, int i) { return int((w >> (31 - i)) & 1u); }

uint32_t from_digits(const int (&d)[32])
{
    uint32_t w = 0;
    for (int i = 0; i < 32; ++i)
        w |= uint32_t(d[i]) << (31 - i);
    return w;
}

// x = C k over GF(2): digit i of x is the parity of the bits j of k with C(i, j) = 1.
template <typename Entry>
uint32_t generate(uint32_t k, Entry entry)
{
    int d[32] = {};
    for (int i = 0; i < 32; ++i)
        for (int j = 0; j < 32; ++j)
            d[i] ^= entry(i, j) & int((k >> j) & 1u);
    return from_digits(d);
}

// The digits of w in reverse order, as a word: digit i becomes bit i.
uint32_t digits_as_bits(uint32_t w)
{
    uint32_t r = 0;
    for (int i = 0; i < 32; ++i)
        r |= uint32_t(digit(w, i)) << i;
    return r;
}

uint32_t bits_as_digits(uint32_t r)
{
    int d[32] = {};
    for (int i = 0; i < 32; ++i)
        d[i] = int((r >> i) & 1u);
    return from_digits(d);
}

uint32_t mix32(uint32_t x)
{
    uint64_t h = x;
    h ^= h >> 16;
    h = (h * 0x21f0aaadull) & mask32;
    h ^= h >> 15;
    h = (h * 0x735a2d97ull) & mask32;
    h ^= h >> 15;
    return uint32_t(h);
}

}  // namespace

uint32_t owen_scramble(uint32_t w, uint32_t key)
{
    uint64_t r = digits_as_bits(w);
    r = (r + key) & mask32;
    for (uint64_t c : {0x6c50b47cull, 0xb82f1e52ull, 0xc7afe638ull, 0x8d22f6e6ull})
        r ^= (r * c) & mask32;
    return bits_as_digits(uint32_t(r));
}

std::array<uint32_t, 2> sobol_points(uint32_t k)
{
    const uint32_t x1 = generate(k, [](int i, int j) { return int(i == j); });
    const uint32_t x2 = generate(k, [](int i, int j) { return int((i & j) == i); });
    return {x1, x2};
}

std::array<uint32_t, 2> sobol_words(uint32_t seed, uint64_t index)
{
    const uint32_t block = uint32_t(index >> 32);
    const std::array<uint32_t, 2> x = sobol_points(uint32_t(index));
    std::array<uint32_t, 2> w{};
    for (uint32_t dimension = 0; dimension < 2; ++dimension) {
        const uint32_t key = mix32(seed ^ mix32(block ^ mix32(uint32_t((dimension + 0x9e3779b9ull) & mask32))));
        w[dimension] = owen_scramble(x[dimension], key);
    }
    return w;
}

// u = (w >> 8) 2^-24, as for Philox.
std::array<double, 2> sobol_uniforms(uint64_t seed, uint64_t index)
{
    constexpr double scale = 1.0 / 16777216.0;
    const auto w = sobol_words(uint32_t(seed), index);
    return {double(w[0] >> 8) * scale, double(w[1] >> 8) * scale};
}

}  // namespace ggxref
