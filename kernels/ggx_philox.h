// ggx_philox.h - Philox2x32-10 counter-based generator (Salmon et al. 2011,
// "Parallel random numbers: as easy as 1, 2, 3") and the uniforms every
// sampler consumes.  Sample `index` of stream `seed` (0 .. 2^32 - 1: the
// generator's key is one 32-bit word) uses
//   key     = seed
//   counter = (index_lo, index_hi)
// and its two output words give u1 (word 0) and u2 (word 1), so host and
// device see the same numbers whatever the chunking.  A dielectric's third
// uniform, the lobe choice, is word 0 of a second block of the same key at
// counter (index_lo, index_hi xor 2^31): the counters of indices 2^63 and up,
// which a stream of indices below 2^63 never uses for its u1, u2 (docs/MATH.md "Uniforms").  The host
// checks this file bit for bit against the Random123 library (tests/).
#ifndef GGX_PHILOX_H
#define GGX_PHILOX_H

#include "ggx_common.h"

#define GGX_PHILOX_M 0xD256D193u
#define GGX_PHILOX_W 0x9E3779B9u

// Two 32-bit words (a Philox counter, two Sobol coordinates) and two uniforms,
// as structs: the shading languages have no pointers.
struct ggx_word_pair {
    ggx_uint w1, w2;
};
GGX_TYPEDEF_STRUCT(ggx_word_pair)
struct ggx_uniform_pair {
    float u1, u2;
};
GGX_TYPEDEF_STRUCT(ggx_uniform_pair)

// Philox2x32 with 10 rounds of counter c: each round one 32x32->64
// multiply, its high half xored with the other word and the key; the key is
// bumped by the Weyl constant between rounds.  Fully unrolled, on two scalar
// words: a loop here, inside PoCL's loop over work-items, keeps the kernel
// from vectorizing, and a struct carried through the rounds costs PoCL 5-10%.
GGX_INLINE ggx_word_pair ggx_philox2x32_10(ggx_word_pair c, ggx_uint k)
{
    ggx_uint c0 = c.w1, c1 = c.w2;
GGX_UNROLL
    for (int round = 0; round < 10; ++round) {
        ggx_ulong product = ggx_to_ulong(GGX_PHILOX_M) * ggx_to_ulong(c0);
        c0 = ggx_to_uint(product >> 32) ^ c1 ^ k;
        c1 = ggx_to_uint(product);
        k += GGX_PHILOX_W;
    }
    ggx_word_pair result;
    result.w1 = c0;
    result.w2 = c1;
    return result;
}

// A 32-bit word to a float in [0, 1): its top 24 bits times 2^-24 (exact, never 1).
GGX_INLINE float ggx_word_to_unit(ggx_uint word)
{
    return ggx_to_float(word >> 8) * 5.9604644775390625e-8f;
}

// The counter of sample `index`, its high word xored with `flip`.
GGX_INLINE ggx_word_pair ggx_philox_counter(ggx_ulong index, ggx_uint flip)
{
    ggx_word_pair c;
    c.w1 = ggx_to_uint(index);
    c.w2 = ggx_to_uint(index >> 32) ^ flip;
    return c;
}

// The two uniforms (u1, u2) of sample `index` in stream `seed` (its low 32 bits).
GGX_INLINE ggx_uniform_pair ggx_philox_pair(ggx_ulong seed, ggx_ulong index)
{
    ggx_word_pair words = ggx_philox2x32_10(ggx_philox_counter(index, 0u), ggx_to_uint(seed));
    ggx_uniform_pair u;
    u.u1 = ggx_word_to_unit(words.w1);
    u.u2 = ggx_word_to_unit(words.w2);
    return u;
}

#if !GGX_SHADER
// The same through pointers, for the C family: ggx_uniforms(seed, index, &u1, &u2).
GGX_INLINE void ggx_uniforms(ggx_ulong seed, ggx_ulong index, float* u1, float* u2)
{
    ggx_uniform_pair u = ggx_philox_pair(seed, index);
    *u1 = u.u1;
    *u2 = u.u2;
}
#endif

// The third uniform of sample `index` in stream `seed`, for dielectrics (see above).
GGX_INLINE float ggx_lobe_uniform(ggx_ulong seed, ggx_ulong index)
{
    return ggx_word_to_unit(ggx_philox2x32_10(ggx_philox_counter(index, 0x80000000u), ggx_to_uint(seed)).w1);
}

#endif
