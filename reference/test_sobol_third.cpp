// test_sobol_third.cpp - the dielectric's third uniform: Sobol's third dimension (its direction
// numbers against Bratley & Fox's recurrence in 32-bit form; with the first two dimensions a
// (1, m, 3)-net, alone a (0, m, 1)-net, scrambled or not; a wrong direction number breaks it) and
// the Philox lobe uniform against Random123 itself.
#include <doctest/doctest.h>

#include <Random123/philox.h>

#include <functional>

#include "ggx_reference.hpp"

using namespace ggxref;

namespace {

// The xor of v[j] over the bits j of k.
uint32_t from_directions(const std::array<uint32_t, 32>& v, uint32_t k)
{
    uint32_t x = 0;
    for (int j = 0; j < 32; ++j)
        if ((k >> j) & 1u)
            x ^= v[j];
    return x;
}

using Point = std::array<uint32_t, 3>;
using Points = std::vector<Point>;

Points first_points(const std::function<Point(uint32_t)>& point, int m)
{
    Points p;
    for (uint32_t k = 0; k < (1u << m); ++k)
        p.push_back(point(k));
    return p;
}

// The first 2^m points form a (t, m, s)-net in base 2 (s = the dimensions listed) iff every
// elementary box with d_1 + ... + d_s = m - t leading digits holds exactly 2^t points.
bool is_net(const Points& points, const std::vector<int>& dims, int m, int t)
{
    const int s = int(dims.size()), digits = m - t;
    std::vector<int> d(s, 0);
    std::function<bool(int, int)> split = [&](int axis, int left) -> bool {
        if (axis == s - 1) {
            d[axis] = left;
            std::vector<int> boxes(size_t(1) << digits, 0);
            for (uint32_t k = 0; k < (1u << m); ++k) {
                uint32_t box = 0;  // the leading d_a digits of each coordinate, concatenated
                for (int a = 0; a < s; ++a)
                    box = d[a] == 0 ? box : (box << d[a]) | (points[k][dims[a]] >> (32 - d[a]));
                ++boxes[box];
            }
            for (int count : boxes)
                if (count != (1 << t))
                    return false;
            return true;
        }
        for (d[axis] = 0; d[axis] <= left; ++d[axis])
            if (!split(axis + 1, left - d[axis]))
                return false;
        return true;
    };
    return split(0, digits);
}

Point unscrambled(uint32_t k)
{
    const auto x = sobol_points(k);
    return {x[0], x[1], sobol_third_point(k)};
}

}  // namespace

TEST_CASE("Sobol's third dimension: direction numbers 0x8, 0xc, 0x6, 0x9 ... of x^2 + x + 1")
{
    const std::array<uint32_t, 32> v = sobol_third_directions();
    CHECK(v[0] == 0x80000000u);
    CHECK(v[1] == 0xc0000000u);
    CHECK(v[2] == 0x60000000u);
    CHECK(v[3] == 0x90000000u);
    // For v_j = m_j 2^(32 - j) the recurrence reads v_j = v_(j-1) xor v_(j-2) xor v_(j-2) / 4.
    for (int j = 2; j < 32; ++j)
        CHECK(v[j] == (v[j - 1] ^ v[j - 2] ^ (v[j - 2] >> 2)));
    for (int j = 0; j < 32; ++j)
        CHECK(((v[j] >> (31 - j)) & 1u) == 1u);  // m_j odd: the generator matrix is upper triangular, invertible
    for (uint32_t k : {0u, 1u, 2u, 3u, 5u, 1000u, 0xfffffffeu, 0xffffffffu})
        CHECK(sobol_third_point(k) == from_directions(v, k));
    CHECK(sobol_third_point(1) == 0x80000000u);
    CHECK(sobol_third_point(2) == 0xc0000000u);
    CHECK(sobol_third_point(3) == 0x40000000u);
}

TEST_CASE("dimensions 1, 2, 3 form a (1, m, 3)-net and dimension 3 a (0, m, 1)-net, scrambled or not")
{
    const Points plain = first_points(unscrambled, 12);
    for (int m = 1; m <= 12; ++m) {
        CAPTURE(m);
        CHECK(is_net(plain, {0, 1, 2}, m, 1));
        CHECK(is_net(plain, {2}, m, 0));
        CHECK(is_net(plain, {0, 1}, m, 0));
    }
    for (uint32_t seed : {1u, 42u, 0xdeadbeefu}) {
        auto scrambled = [seed](uint32_t k) {
            const auto w = sobol_words(seed, k);
            return Point{w[0], w[1], sobol_third_word(seed, k)};
        };
        const Points points = first_points(scrambled, 12);
        for (int m : {4, 8, 12}) {
            CAPTURE(seed);
            CAPTURE(m);
            CHECK(is_net(points, {0, 1, 2}, m, 1));
            CHECK(is_net(points, {2}, m, 0));
            CHECK(!is_net(points, {0, 1, 2}, m, 0));  // t = 1 is the best these three reach
        }
    }
}

TEST_CASE("negative control: a wrong direction number breaks the net property")
{
    std::array<uint32_t, 32> v = sobol_third_directions();
    v[3] = 0xb0000000u;  // m_4 = 11 instead of 9: still odd, still a (0, m, 1)-net alone
    auto wrong = [&v](uint32_t k) {
        const auto x = sobol_points(k);
        return Point{x[0], x[1], from_directions(v, k)};
    };
    const Points points = first_points(wrong, 8);
    bool broken = false;
    for (int m = 1; m <= 8; ++m)
        broken = broken || !is_net(points, {0, 1, 2}, m, 1);
    CHECK(broken);
    CHECK(is_net(points, {2}, 8, 0));
}

TEST_CASE("lobe uniforms: the scrambled third word's top 24 bits; Philox word 0 at counter (lo, hi ^ 2^31)")
{
    for (uint64_t index : {0ull, 1ull, 77ull, 0xffffffffull, 0x100000005ull, 0xfedcba9876543210ull}) {
        const double u = lobe_uniform_sobol(0x1234567890ull, index);
        CHECK(u * 16777216.0 == double(sobol_third_word(0x34567890u, index) >> 8));
        CHECK(u < 1.0);
        r123::Philox2x32_R<10> rng;
        const r123::Philox2x32_R<10>::ctr_type c = {{uint32_t(index), uint32_t(index >> 32) ^ 0x80000000u}};
        const r123::Philox2x32_R<10>::key_type k = {{0x34567890u}};
        CHECK(lobe_uniform_philox(0x1234567890ull, index) * 16777216.0 == double(rng(c, k)[0] >> 8));
        CHECK(lobe_uniform_philox(0x1234567890ull, index) != uniforms(0x1234567890ull, index)[0]);
    }
    // Random123's known answer: philox2x32_10(counter {0, 0}, key 0) = {0xff1dae59, 0x6cd10df2}; index
    // 2^63 of seed 0 reaches that counter through the xor.
    CHECK(lobe_uniform_philox(0, 0x8000000000000000ull) * 16777216.0 == double(0xff1dae59u >> 8));
    // A new 2^32 block of indices gets a new scramble.
    CHECK(sobol_third_word(5, 3) != sobol_third_word(5, 3 + (1ull << 32)));
    CHECK(sobol_third_word(5, 3) != sobol_third_word(6, 3));
}
