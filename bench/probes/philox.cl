// philox.cl - cost probe for bench/probe_kernel (see docs/BENCHMARKS.md): 4 floats written per work-item.
__kernel void k(__global float* out, uint count) {
  uint j = get_global_id(0);
  float u1, u2; ggx_uniforms(12345ul, (ulong)j, &u1, &u2);
  out[j] = u1; out[j + count] = u2; out[j + 2*count] = u1; out[j + 3*count] = u2;
}
