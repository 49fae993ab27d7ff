// ggx_philox.h - Philox4x32-10 counter-based generator (Salmon et al. 2011,
// "Parallel random numbers: as easy as 1, 2, 3") and the uniforms every
// sampler consumes.  Sample `index` of stream `seed` uses
//   key     = (seed_lo, seed_hi)
//   counter = (index_lo, index_hi, 0, 0)
// so host and device see the same numbers whatever the chunking.  The host
// checks this file bit for bit against the Random123 library (tests/).
#ifndef GGX_PHILOX_H
#define GGX_PHILOX_H

#include "ggx_common.h"

#define GGX_PHILOX_M0 0xD2511F53u
#define GGX_PHILOX_M1 0xCD9E8D57u
#define GGX_PHILOX_W0 0x9E3779B9u
#define GGX_PHILOX_W1 0xBB67AE85u

// One Philox round: two 32x32->64 multiplies, xor with the other words and key.
GGX_INLINE void ggx_philox_round(uint* c0, uint* c1, uint* c2, uint* c3, uint k0, uint k1)
{
    ulong p0 = (ulong)GGX_PHILOX_M0 * (ulong)(*c0);
    ulong p1 = (ulong)GGX_PHILOX_M1 * (ulong)(*c2);
    uint hi0 = (uint)(p0 >> 32), lo0 = (uint)p0;
    uint hi1 = (uint)(p1 >> 32), lo1 = (uint)p1;
    uint n0 = hi1 ^ *c1 ^ k0;
    uint n2 = hi0 ^ *c3 ^ k1;
    *c0 = n0;
    *c1 = lo1;
    *c2 = n2;
    *c3 = lo0;
}

// Philox4x32 with 10 rounds; the key is bumped by the Weyl constants between
// rounds.  Fully unrolled: a loop here, inside PoCL's loop over work-items,
// keeps the kernel from vectorizing.
GGX_INLINE void ggx_philox4x32_10(uint* c0, uint* c1, uint* c2, uint* c3, uint k0, uint k1)
{
#pragma unroll
    for (int round = 0; round < 10; ++round) {
        ggx_philox_round(c0, c1, c2, c3, k0, k1);
        k0 += GGX_PHILOX_W0;
        k1 += GGX_PHILOX_W1;
    }
}

// A 32-bit word to a float in [0, 1): its top 24 bits times 2^-24 (exact, never 1).
GGX_INLINE float ggx_word_to_unit(uint word)
{
    return (float)(word >> 8) * 5.9604644775390625e-8f;
}

// The two uniforms (u1, u2) of sample `index` in stream `seed`.
GGX_INLINE void ggx_uniforms(ulong seed, ulong index, float* u1, float* u2)
{
    uint c0 = (uint)index, c1 = (uint)(index >> 32), c2 = 0u, c3 = 0u;
    ggx_philox4x32_10(&c0, &c1, &c2, &c3, (uint)seed, (uint)(seed >> 32));
    *u1 = ggx_word_to_unit(c0);
    *u2 = ggx_word_to_unit(c1);
}

#endif
