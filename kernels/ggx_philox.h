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

// One Philox2x32 round: one 32x32->64 multiply, its high half xored with the
// other word and the key.
GGX_INLINE void ggx_philox_round(ggx_uint* c0, ggx_uint* c1, ggx_uint k)
{
    ggx_ulong product = (ggx_ulong)GGX_PHILOX_M * (ggx_ulong)(*c0);
    ggx_uint hi = (ggx_uint)(product >> 32), lo = (ggx_uint)product;
    *c0 = hi ^ *c1 ^ k;
    *c1 = lo;
}

// Philox2x32 with 10 rounds; the key is bumped by the Weyl constant between
// rounds.  Fully unrolled: a loop here, inside PoCL's loop over work-items,
// keeps the kernel from vectorizing.
GGX_INLINE void ggx_philox2x32_10(ggx_uint* c0, ggx_uint* c1, ggx_uint k)
{
GGX_UNROLL
    for (int round = 0; round < 10; ++round) {
        ggx_philox_round(c0, c1, k);
        k += GGX_PHILOX_W;
    }
}

// A 32-bit word to a float in [0, 1): its top 24 bits times 2^-24 (exact, never 1).
GGX_INLINE float ggx_word_to_unit(ggx_uint word)
{
    return (float)(word >> 8) * 5.9604644775390625e-8f;
}

// The two uniforms (u1, u2) of sample `index` in stream `seed` (its low 32 bits).
GGX_INLINE void ggx_uniforms(ggx_ulong seed, ggx_ulong index, float* u1, float* u2)
{
    ggx_uint c0 = (ggx_uint)index, c1 = (ggx_uint)(index >> 32);
    ggx_philox2x32_10(&c0, &c1, (ggx_uint)seed);
    *u1 = ggx_word_to_unit(c0);
    *u2 = ggx_word_to_unit(c1);
}

// The third uniform of sample `index` in stream `seed`, for dielectrics (see above).
GGX_INLINE float ggx_lobe_uniform(ggx_ulong seed, ggx_ulong index)
{
    ggx_uint c0 = (ggx_uint)index, c1 = (ggx_uint)(index >> 32) ^ 0x80000000u;
    ggx_philox2x32_10(&c0, &c1, (ggx_uint)seed);
    return ggx_word_to_unit(c0);
}

#endif
