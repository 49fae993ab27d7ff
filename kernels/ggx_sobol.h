// ggx_sobol.h - the first two dimensions of the Sobol sequence in base 2,
// Owen-scrambled by a hash keyed by the seed (Burley 2020, "Practical
// Hash-based Owen Scrambling", JCGT 9(4)), as an alternative to Philox for
// the two uniforms of a sample.  Point k is sample index k, so chunks,
// shards and device splits give the same points.  docs/MATH.md "Uniforms"
// states the construction; the host reference (reference/ggx_sobol.cpp)
// computes it independently, and tests/samplers/test_sobol.cpp checks them
// bit for bit and checks the (0, m, 2)-net property.
//
// Sample `index` of stream `seed`:
//   x1 = bits of the low word of index reversed (van der Corput),
//   x2 = the low word of index times the Pascal matrix mod 2 (Sobol's second
//        dimension: direction numbers v_0 = 2^31, v_j = v_{j-1} xor v_{j-1}/2),
//   each scrambled by ggx_owen_scramble with its own key from (seed,
//   dimension, high word of index): a stream beyond 2^32 samples continues
//   with new scrambles; u = top 24 bits times 2^-24, as for Philox.
#ifndef GGX_SOBOL_H
#define GGX_SOBOL_H

#include "ggx_philox.h"

// The 32 bits of x in reverse order.
GGX_INLINE uint ggx_reverse_bits(uint x)
{
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

// Sobol's second dimension of point k: the xor of the direction numbers of k's set bits.
GGX_INLINE uint ggx_sobol_second(uint k)
{
    uint x = 0u, v = 0x80000000u;
#pragma unroll
    for (int bit = 0; bit < 32; ++bit) {
        x ^= ((k >> bit) & 1u) ? v : 0u;
        v ^= v >> 1;
    }
    return x;
}

// A nested uniform (Owen) scramble of the binary fraction x / 2^32 with key
// `key`: with the bits reversed, digit i of the fraction is bit i, and each
// step below changes bit i by a function of bits 0 .. i - 1 alone (adding
// the key carries only upward; x * c with c even moves bits only upward), so
// digit i is flipped by a function of the digits above it: an Owen scramble
// (Burley 2020, sec. 3, with his Laine-Karras-style constants).
GGX_INLINE uint ggx_owen_scramble(uint x, uint key)
{
    x = ggx_reverse_bits(x);
    x += key;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return ggx_reverse_bits(x);
}

// A 32-bit mix (xorshift-multiply, full avalanche) for the scramble keys.
GGX_INLINE uint ggx_mix32(uint x)
{
    x ^= x >> 16;
    x *= 0x21f0aaadu;
    x ^= x >> 15;
    x *= 0x735a2d97u;
    x ^= x >> 15;
    return x;
}

// The scramble key of `dimension` (0 or 1) for stream `seed` and the samples
// of one 2^32 block (`block`: the index's high word).
GGX_INLINE uint ggx_sobol_key(uint seed, uint dimension, uint block)
{
    return ggx_mix32(seed ^ ggx_mix32(block ^ ggx_mix32(dimension + 0x9e3779b9u)));
}

// The two scrambled 32-bit coordinates of sample `index` of stream `seed`.
GGX_INLINE void ggx_sobol_words(ulong seed, ulong index, uint* w1, uint* w2)
{
    uint k = (uint)index, block = (uint)(index >> 32);
    *w1 = ggx_owen_scramble(ggx_reverse_bits(k), ggx_sobol_key((uint)seed, 0u, block));
    *w2 = ggx_owen_scramble(ggx_sobol_second(k), ggx_sobol_key((uint)seed, 1u, block));
}

// The two uniforms of sample `index` in stream `seed` from the scrambled Sobol points.
GGX_INLINE void ggx_sobol_uniforms(ulong seed, ulong index, float* u1, float* u2)
{
    uint w1, w2;
    ggx_sobol_words(seed, index, &w1, &w2);
    *u1 = ggx_word_to_unit(w1);
    *u2 = ggx_word_to_unit(w2);
}

#endif
