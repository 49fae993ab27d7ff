// ggx_stress.cl - the stability map's kernel (`ggx stress`): every case
// brings its own roughness, view, normal and uniforms, so that the sweep
// reaches inputs the runtime's validation refuses (an alpha of exactly 0)
// and uniforms at the edges of [0, 1).  It calls the device functions as a
// user kernel would (ggx_sample_<method> through ggx_sample_method, and
// ggx_pdf_method on the returned direction).
//
// Build options: GGX_METHOD=<id>, GGX_GUARDS, GGX_DIELECTRIC, the device's
// own (ggxcl::device_options) and the precision mode's
// (ggxcl::precision_options).  Layout: case j reads in[k * count + j] for
// k = ax, ay, view x, y, z, normal x, y, z, u1, u2 and writes
// out[k * count + j] for k = m x, y, z, o x, y, z, pdf_m, pdf_o, weight,
// pdf of o recomputed from (i, o).
// With GGX_DIELECTRIC=1 it samples the rough dielectric instead
// (ggx_sample_dielectric_method, radiance transport, and
// ggx_pdf_dielectric_method of the returned direction): two more inputs,
// k = 10 the lobe's uniform u3 and k = 11 the relative index eta, and one
// more output, k = 10 the weight of the same sample in importance transport.
#include "ggx_kernel_io.h"
#include "ggx_samplers.h"

#ifndef GGX_METHOD
#error "build with -DGGX_METHOD=<method id>"
#endif

#if GGX_DIELECTRIC
#include "ggx_dielectric.h"
#define GGX_STRESS_OUTPUTS 11u
#else
#define GGX_STRESS_OUTPUTS 10u
#endif

__kernel void ggx_stress(uint count, __global const float* GGX_RESTRICT in, __global float* GGX_RESTRICT out)
{
    uint j = (uint)get_global_id(0);
    if (j >= count)
        return;
    float ax = in[j], ay = in[count + j];
    ggx_vec3 i = ggx_vec3_make(in[2u * count + j], in[3u * count + j], in[4u * count + j]);
    ggx_vec3 n = ggx_vec3_make(in[5u * count + j], in[6u * count + j], in[7u * count + j]);
    float u1 = in[8u * count + j], u2 = in[9u * count + j];
#if GGX_DIELECTRIC
    float u3 = in[10u * count + j], eta = in[11u * count + j];
    ggx_sample s = ggx_sample_dielectric_method(GGX_METHOD, n, i, ax, ay, eta, 1, u1, u2, u3);
    ggx_sample imp = ggx_sample_dielectric_method(GGX_METHOD, n, i, ax, ay, eta, 0, u1, u2, u3);
    float values[GGX_STRESS_OUTPUTS] = {s.m.x,    s.m.y,    s.m.z,
                                        s.o.x,    s.o.y,    s.o.z,
                                        s.pdf_m,  s.pdf_o,  s.weight,
                                        ggx_pdf_dielectric_method(GGX_METHOD, n, i, s.o, ax, ay, eta), imp.weight};
#else
    ggx_sample s = ggx_sample_method(GGX_METHOD, n, i, ax, ay, u1, u2);
    float values[GGX_STRESS_OUTPUTS] = {s.m.x, s.m.y, s.m.z, s.o.x, s.o.y, s.o.z, s.pdf_m, s.pdf_o, s.weight,
                                        ggx_pdf_method(GGX_METHOD, n, i, s.o, ax, ay)};
#endif
    for (uint k = 0; k < GGX_STRESS_OUTPUTS; ++k)
        out[k * count + j] = values[k];
}
