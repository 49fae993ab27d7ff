// philox_mul_hi.cl - cost probe for bench/probe_kernel (see docs/BENCHMARKS.md): 4 floats written per work-item.
GGX_INLINE void round2(uint* c0, uint* c1, uint* c2, uint* c3, uint k0, uint k1)
{
    uint hi0 = mul_hi(GGX_PHILOX_M0, *c0), lo0 = GGX_PHILOX_M0 * *c0;
    uint hi1 = mul_hi(GGX_PHILOX_M1, *c2), lo1 = GGX_PHILOX_M1 * *c2;
    uint n0 = hi1 ^ *c1 ^ k0, n2 = hi0 ^ *c3 ^ k1;
    *c0 = n0; *c1 = lo1; *c2 = n2; *c3 = lo0;
}
__kernel void k(__global float* out, uint count) {
  uint j = get_global_id(0);
  uint c0 = j, c1 = 0, c2 = 0, c3 = 0, k0 = 12345u, k1 = 0u;
#pragma unroll
  for (int r = 0; r < 10; ++r) { round2(&c0, &c1, &c2, &c3, k0, k1); k0 += GGX_PHILOX_W0; k1 += GGX_PHILOX_W1; }
  float u1 = ggx_word_to_unit(c0), u2 = ggx_word_to_unit(c1);
  out[j] = u1; out[j + count] = u2; out[j + 2*count] = u1; out[j + 3*count] = u2;
}
