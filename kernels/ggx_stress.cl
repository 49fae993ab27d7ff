// ggx_stress.cl - the stability map's kernel (`ggx stress`): every case
// brings its own roughness, view, normal and uniforms, so that the sweep
// reaches inputs the runtime's validation refuses (an alpha of exactly 0)
// and uniforms at the edges of [0, 1).  What a case computes is
// ggx_stress_case.h's, shared with the stress shaders (ggx_stress.comp, .hlsl).
//
// Build options: GGX_METHOD=<id>, GGX_GUARDS, GGX_DIELECTRIC, the device's
// own (ggxcl::device_options) and the precision mode's
// (ggxcl::precision_options).  Layout: case j reads in[k * count + j] for
// k = ax, ay, view x, y, z, normal x, y, z, u1, u2 (and with GGX_DIELECTRIC
// k = 10 the lobe's uniform u3, k = 11 the relative index eta) and writes
// out[k * count + j] for the outputs of ggx_stress_case.h.
#include "ggx_kernel_io.h"
#include "ggx_stress_case.h"

__kernel void ggx_stress(uint count, __global const float* GGX_RESTRICT in, __global float* GGX_RESTRICT out)
{
    uint j = (uint)get_global_id(0);
    if (j >= count)
        return;
    ggx_stress_input c;
    c.ax = in[j];
    c.ay = in[count + j];
    c.i = ggx_vec3_make(in[2u * count + j], in[3u * count + j], in[4u * count + j]);
    c.n = ggx_vec3_make(in[5u * count + j], in[6u * count + j], in[7u * count + j]);
    c.u1 = in[8u * count + j];
    c.u2 = in[9u * count + j];
#if GGX_DIELECTRIC
    c.u3 = in[10u * count + j];
    c.eta = in[11u * count + j];
#else
    c.u3 = 0.0f;
    c.eta = 1.0f;
#endif
    ggx_stress_result r = ggx_stress_case(c);
    for (uint k = 0; k < GGX_STRESS_OUTPUTS; ++k)
        out[k * count + j] = ggx_stress_output(r, k);
}
