// ggx_philox.cpp - the counter-based uniforms shared by host and device: Random123 Philox2x32-10
// keyed by the seed and counting the sample index, top 24 bits of a word as a float-exact uniform;
// a dielectric's lobe choice from a second block with the top bit of the counter's high word flipped.
#include <Random123/philox.h>

#include "ggx_reference.hpp"

namespace ggxref {

std::array<uint32_t, 2> philox2x32_10(const std::array<uint32_t, 2>& counter, uint32_t key)
{
    r123::Philox2x32_R<10> rng;
    const r123::Philox2x32_R<10>::ctr_type c = {{counter[0], counter[1]}};
    const r123::Philox2x32_R<10>::key_type k = {{key}};
    const auto r = rng(c, k);
    return {r[0], r[1]};
}

std::array<uint32_t, 2> philox_words(uint32_t seed, uint64_t index)
{
    return philox2x32_10({uint32_t(index), uint32_t(index >> 32)}, seed);
}

// u = (w >> 8) 2^-24: exact in float, in [0, 1 - 2^-24].
std::array<double, 2> uniforms(uint64_t seed, uint64_t index)
{
    constexpr double scale = 1.0 / 16777216.0;
    const auto w = philox_words(uint32_t(seed), index);
    return {double(w[0] >> 8) * scale, double(w[1] >> 8) * scale};
}

// Word 0 of the block at counter (index lo, index hi xor 2^31): counters a stream's u1, u2 reach only
// past index 2^63.
double lobe_uniform_philox(uint64_t seed, uint64_t index)
{
    const uint32_t w0 = philox2x32_10({uint32_t(index), uint32_t(index >> 32) ^ 0x80000000u}, uint32_t(seed))[0];
    return double(w0 >> 8) / 16777216.0;
}

}  // namespace ggxref
