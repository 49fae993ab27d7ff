// caps_no_pdf.cl - cost probe for bench/probe_kernel (see docs/BENCHMARKS.md): 4 floats written per work-item.
__kernel void k(__global float* out, uint count) {
  uint j = get_global_id(0);
  float u1, u2; ggx_uniforms(12345ul, (ulong)j, &u1, &u2);
  ggx_sample s = ggx_sample_caps(ggx_vec3_make(0.866f, 0.f, 0.5f), 0.3f, 0.3f, u1, u2);
  out[j] = s.m.x; out[j + count] = s.m.y; out[j + 2*count] = s.m.z; out[j + 3*count] = u1;
}
