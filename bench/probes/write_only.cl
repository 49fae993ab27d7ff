// write_only.cl - cost probe for bench/probe_kernel (see docs/BENCHMARKS.md): 4 floats written per work-item.
__kernel void k(__global float* out, uint count) {
  uint j = get_global_id(0);
  float x = j * 1e-7f;
  out[j] = x; out[j + count] = x; out[j + 2*count] = x; out[j + 3*count] = x;
}
