// test_philox.cpp - Random123 Philox4x32-10 known answers and the seed/index -> uniforms mapping.
#include <doctest/doctest.h>

#include "ggx_reference.hpp"

using namespace ggxref;

TEST_CASE("philox4x32-10 known-answer vectors")
{
    using W = std::array<uint32_t, 4>;
    CHECK(philox4x32_10({0, 0, 0, 0}, {0, 0}) == W{0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8});
    CHECK(philox4x32_10({0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff}, {0xffffffff, 0xffffffff}) ==
          W{0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd});
    CHECK(philox4x32_10({0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344}, {0xa4093822, 0x299f31d0}) ==
          W{0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1});
    CHECK(philox_words(0, 0) == W{0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8});
}

TEST_CASE("philox_words: key = seed halves, counter = index halves")
{
    const uint64_t seed = 0x0123456789abcdefULL, index = 0xfedcba9876543210ULL;
    CHECK(philox_words(seed, index) == philox4x32_10({0x76543210, 0xfedcba98, 0, 0}, {0x89abcdef, 0x01234567}));
    CHECK(philox_words(seed, index) != philox_words(seed, index + 1));
    CHECK(philox_words(seed, index) != philox_words(seed + 1, index));
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
