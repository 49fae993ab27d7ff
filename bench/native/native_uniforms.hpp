// native_uniforms.hpp - the two uniforms of sample `index` in stream `seed`: Random123
// Philox2x32-10 with key = seed (32 bits) and counter = {index lo, index hi}; each
// uniform is the top 24 bits of a word times 2^-24 (exact in float, in [0, 1)).  The same stream
// as the kernels (ggx_philox.h) and the reference (ggxref::uniforms).
#pragma once

#include <cstdint>

#include <Random123/philox.h>

namespace ggxnative {

struct Uniforms {
    float u1, u2;
};

inline float word_to_unit(std::uint32_t word) { return float(word >> 8) * 5.9604644775390625e-8f; }

inline Uniforms uniforms(std::uint64_t seed, std::uint64_t index)
{
    using Philox = r123::Philox2x32_R<10>;
    Philox philox;
    Philox::ctr_type counter = {{std::uint32_t(index), std::uint32_t(index >> 32)}};
    Philox::key_type key = {{std::uint32_t(seed)}};
    Philox::ctr_type words = philox(counter, key);
    return {word_to_unit(words[0]), word_to_unit(words[1])};
}

}  // namespace ggxnative
