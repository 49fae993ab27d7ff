// test_philox.cpp - Random123 Philox2x32-10 known answers and the seed/index -> uniforms mapping.
#include <doctest/doctest.h>

#include "ggx_reference.hpp"

using namespace ggxref;

TEST_CASE("philox2x32-10 known-answer vectors")
{
    // Random123's kat_vectors: philox2x32 10 rounds, (counter, key) -> output.
    using W = std::array<uint32_t, 2>;
    CHECK(philox2x32_10({0, 0}, 0) == W{0xff1dae59, 0x6cd10df2});
    CHECK(philox2x32_10({0xffffffff, 0xffffffff}, 0xffffffff) == W{0x2c3f628b, 0xab4fd7ad});
    CHECK(philox2x32_10({0x243f6a88, 0x85a308d3}, 0x13198a2e) == W{0xdd7ce038, 0xf62a4c12});
    CHECK(philox_words(0, 0) == W{0xff1dae59, 0x6cd10df2});
}

TEST_CASE("philox_words: key = seed, counter = index halves")
{
    const uint32_t seed = 0x89abcdefu;
    const uint64_t index = 0xfedcba9876543210ULL;
    CHECK(philox_words(seed, index) == philox2x32_10({0x76543210, 0xfedcba98}, 0x89abcdef));
    CHECK(philox_words(seed, index) != philox_words(seed, index + 1));
    CHECK(philox_words(seed, index) != philox_words(seed + 1, index));
    CHECK(philox_words(seed, index) != philox_words(seed, index + (1ull << 32)));  // both counter words count
}

TEST_CASE("uniforms are the top 24 bits of words 0 and 1")
{
    for (uint64_t index = 0; index < 1000; ++index) {
        const auto w = philox_words(42, index);
        const auto u = uniforms(42, index);
        CHECK(u[0] * 16777216.0 == double(w[0] >> 8));
        CHECK(u[1] * 16777216.0 == double(w[1] >> 8));
        CHECK(u[0] >= 0.0);
        CHECK(u[0] < 1.0);
        CHECK(u[1] < 1.0);
        CHECK(double(float(u[0])) == u[0]);  // exact in float
    }
}
