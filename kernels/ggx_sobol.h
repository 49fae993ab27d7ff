// ggx_sobol.h - the first two (three) dimensions of the Sobol sequence in base 2,
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
//   each scrambled by ggx_owen_scramble_digits with its own key from (seed,
//   dimension, high word of index): a stream beyond 2^32 samples continues
//   with new scrambles; u = top 24 bits times 2^-24, as for Philox.
// A dielectric's third uniform (the lobe choice) is Sobol's third dimension,
// scrambled the same way with the key of dimension 2: the first 2^m points
// of the three dimensions form a (1, m, 3)-net, the third alone a (0, m, 1)-net.
#ifndef GGX_SOBOL_H
#define GGX_SOBOL_H

#include "ggx_philox.h"

#ifndef GGX_NO_BITREVERSE
#define GGX_NO_BITREVERSE 0
#endif

#if GGX_NO_BITREVERSE
// The low 8 bits of b in reverse order, by multiplies that no compiler turns
// into llvm.bitreverse (spread 4 copies, pick one bit of each, gather).
GGX_INLINE ggx_uint ggx_reverse_byte(ggx_uint b)
{
    ggx_ulong spread = ggx_to_ulong(b & 0xffu) * ggx_to_ulong(0x80200802u);
    ggx_ulong picked = spread & (ggx_to_ulong(0x08u) << 32 | ggx_to_ulong(0x84422110u));
    return ggx_to_uint((picked * (ggx_to_ulong(0x01u) << 32 | ggx_to_ulong(0x01010101u))) >> 32) & 0xffu;
}
#endif

// The 32 bits of x in reverse order.  Compilers turn the masks and shifts
// into one llvm.bitreverse; -DGGX_NO_BITREVERSE=1 (set by the runtime for
// Oclgrind, whose LLVM does not know that intrinsic) reverses byte by byte.
GGX_INLINE ggx_uint ggx_reverse_bits(ggx_uint x)
{
#if GGX_NO_BITREVERSE
    return (ggx_reverse_byte(x) << 24) | (ggx_reverse_byte(x >> 8) << 16) | (ggx_reverse_byte(x >> 16) << 8) |
           ggx_reverse_byte(x >> 24);
#else
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
#endif
}

// The digits of Sobol's second dimension of point k as bits (digit i of the
// binary fraction = bit i): digit i is the parity of the bits j of k with
// binom(j, i) odd, that is with the bits of i a subset of those of j
// (Lucas), summed over the supersets one index bit at a time.  Straight-line
// code: a loop over k's bits here keeps PoCL from vectorizing the kernels.
GGX_INLINE ggx_uint ggx_sobol_second_digits(ggx_uint k)
{
    k ^= (k >> 1) & 0x55555555u;
    k ^= (k >> 2) & 0x33333333u;
    k ^= (k >> 4) & 0x0f0f0f0fu;
    k ^= (k >> 8) & 0x00ff00ffu;
    k ^= (k >> 16) & 0x0000ffffu;
    return k;
}

// A nested uniform (Owen) scramble with key `key` of the binary fraction
// whose digit i is bit i of `digits`, returned as a 32-bit fraction (most
// significant digit in the top bit): each step below changes bit i by a
// function of bits 0 .. i - 1 alone (adding the key carries only upward;
// x * c with c even moves bits only upward), so digit i is flipped by a
// function of the digits above it: an Owen scramble (Burley 2020, sec. 3,
// with his Laine-Karras-style constants).
GGX_INLINE ggx_uint ggx_owen_scramble_digits(ggx_uint digits, ggx_uint key)
{
    ggx_uint x = digits + key;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return ggx_reverse_bits(x);
}

// The same for a 32-bit fraction x.
GGX_INLINE ggx_uint ggx_owen_scramble(ggx_uint x, ggx_uint key)
{
    return ggx_owen_scramble_digits(ggx_reverse_bits(x), key);
}

// A 32-bit mix (xorshift-multiply, full avalanche) for the scramble keys.
GGX_INLINE ggx_uint ggx_mix32(ggx_uint x)
{
    x ^= x >> 16;
    x *= 0x21f0aaadu;
    x ^= x >> 15;
    x *= 0x735a2d97u;
    x ^= x >> 15;
    return x;
}

// The scramble key of `dimension` (0, 1 or 2) for stream `seed` and the samples
// of one 2^32 block (`block`: the index's high word).
GGX_INLINE ggx_uint ggx_sobol_key(ggx_uint seed, ggx_uint dimension, ggx_uint block)
{
    return ggx_mix32(seed ^ ggx_mix32(block ^ ggx_mix32(dimension + 0x9e3779b9u)));
}

// The two scrambled 32-bit coordinates of point k (the index's low word)
// with the scramble keys of its block.  van der Corput's digits are the bits
// of k themselves.
GGX_INLINE ggx_word_pair ggx_sobol_words_keyed(ggx_uint k, ggx_uint key1, ggx_uint key2)
{
    ggx_word_pair w;
    w.w1 = ggx_owen_scramble_digits(k, key1);
    w.w2 = ggx_owen_scramble_digits(ggx_sobol_second_digits(k), key2);
    return w;
}

// The two scrambled 32-bit coordinates of sample `index` of stream `seed`.
GGX_INLINE ggx_word_pair ggx_sobol_words(ggx_ulong seed, ggx_ulong index)
{
    ggx_uint block = ggx_to_uint(index >> 32);
    return ggx_sobol_words_keyed(ggx_to_uint(index), ggx_sobol_key(ggx_to_uint(seed), 0u, block),
                                 ggx_sobol_key(ggx_to_uint(seed), 1u, block));
}

// The two uniforms of a pair of words.
GGX_INLINE ggx_uniform_pair ggx_words_to_units(ggx_word_pair w)
{
    ggx_uniform_pair u;
    u.u1 = ggx_word_to_unit(w.w1);
    u.u2 = ggx_word_to_unit(w.w2);
    return u;
}

// The two uniforms of sample `index` in stream `seed` from the scrambled Sobol points.
GGX_INLINE ggx_uniform_pair ggx_sobol_pair(ggx_ulong seed, ggx_ulong index)
{
    return ggx_words_to_units(ggx_sobol_words(seed, index));
}

#if !GGX_SHADER
// The same through pointers, for the C family.
GGX_INLINE void ggx_sobol_uniforms(ggx_ulong seed, ggx_ulong index, float* u1, float* u2)
{
    ggx_uniform_pair u = ggx_sobol_pair(seed, index);
    *u1 = u.u1;
    *u2 = u.u2;
}
#endif

// The digits of Sobol's third dimension of point k as a 32-bit fraction: the
// xor of the direction numbers v_j of the bits j of k.  Its primitive
// polynomial x^2 + x + 1 with m_1 = 1, m_2 = 3 gives, for v_j = m_j 2^(32-j),
// the recurrence v_j = v_(j-1) xor v_(j-2) xor v_(j-2) / 4 (Bratley & Fox
// 1988); unrolled, every v_j is a constant.
GGX_INLINE ggx_uint ggx_sobol_third_word(ggx_uint k)
{
    ggx_uint previous = 0x80000000u, current = 0xc0000000u;
    ggx_uint x = (previous & (0u - (k & 1u))) ^ (current & (0u - ((k >> 1) & 1u)));
GGX_UNROLL
    for (int j = 2; j < 32; ++j) {
        ggx_uint next = current ^ previous ^ (previous >> 2);
        x ^= next & (0u - ((k >> j) & 1u));
        previous = current;
        current = next;
    }
    return x;
}

// The third uniform of sample `index` of stream `seed`.
GGX_INLINE float ggx_sobol_lobe_uniform(ggx_ulong seed, ggx_ulong index)
{
    ggx_uint key = ggx_sobol_key(ggx_to_uint(seed), 2u, ggx_to_uint(index >> 32));
    return ggx_word_to_unit(ggx_owen_scramble(ggx_sobol_third_word(ggx_to_uint(index)), key));
}

// The same for sample first + j of a launch of fewer than 2^32 samples,
// which crosses at most one 2^32 block: the keys of both candidate blocks
// depend on (seed, first) alone, so a compiler computes them once per launch
// instead of once per sample (the points cost a third less on PoCL).
GGX_INLINE ggx_uniform_pair ggx_sobol_launch_pair(ggx_ulong seed, ggx_ulong first, ggx_uint j)
{
    ggx_uint block = ggx_to_uint(first >> 32);
    ggx_uint key1 = ggx_sobol_key(ggx_to_uint(seed), 0u, block), key2 = ggx_sobol_key(ggx_to_uint(seed), 1u, block);
    ggx_uint next1 = ggx_sobol_key(ggx_to_uint(seed), 0u, block + 1u);
    ggx_uint next2 = ggx_sobol_key(ggx_to_uint(seed), 1u, block + 1u);
    ggx_ulong index = first + j;
    bool next = ggx_to_uint(index >> 32) != block;
    return ggx_words_to_units(ggx_sobol_words_keyed(ggx_to_uint(index), next ? next1 : key1, next ? next2 : key2));
}

// The third uniform of sample first + j of a launch, its keys per launch as above.
GGX_INLINE float ggx_sobol_launch_lobe_uniform(ggx_ulong seed, ggx_ulong first, ggx_uint j)
{
    ggx_uint block = ggx_to_uint(first >> 32);
    ggx_uint key = ggx_sobol_key(ggx_to_uint(seed), 2u, block);
    ggx_uint next_key = ggx_sobol_key(ggx_to_uint(seed), 2u, block + 1u);
    ggx_ulong index = first + j;
    ggx_uint word = ggx_sobol_third_word(ggx_to_uint(index));
    return ggx_word_to_unit(ggx_owen_scramble(word, ggx_to_uint(index >> 32) != block ? next_key : key));
}

#endif
