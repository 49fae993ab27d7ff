// ggx_stress_case.h - one case of the stability map (`ggx stress`), the same
// text in the OpenCL kernel (ggx_stress.cl) and the shaders (ggx_stress.comp,
// .hlsl, through ggx_stress_shader.h): the device functions called as a
// user's code calls them (ggx_sample_method and ggx_pdf_method of the
// returned direction; with GGX_DIELECTRIC=1 the rough dielectric's, in
// radiance transport, and the same sample's weight in importance
// transport).  Each language loads the case and stores the outputs itself.
// Outputs, in order (GGX_STRESS_OUTPUTS): m x, y, z, o x, y, z, pdf_m, pdf_o,
// weight, the pdf of o recomputed from (i, o), and with GGX_DIELECTRIC the
// importance weight.  Build switches: GGX_METHOD=<id>, GGX_GUARDS,
// GGX_DIELECTRIC.
#ifndef GGX_STRESS_CASE_H
#define GGX_STRESS_CASE_H

#include "ggx_samplers.h"

#ifndef GGX_METHOD
#error "build with -DGGX_METHOD=<method id>"
#endif
#ifndef GGX_DIELECTRIC
#define GGX_DIELECTRIC 0
#endif

#if GGX_DIELECTRIC
#include "ggx_dielectric.h"
#define GGX_STRESS_INPUTS 12u
#define GGX_STRESS_OUTPUTS 11u
#else
#define GGX_STRESS_INPUTS 10u
#define GGX_STRESS_OUTPUTS 10u
#endif

// A case: roughness, view i, normal n, uniforms, and a dielectric's relative index.
struct ggx_stress_input {
    ggx_vec3 i, n;
    float ax, ay, u1, u2, u3, eta;
};
GGX_TYPEDEF_STRUCT(ggx_stress_input)

struct ggx_stress_result {
    ggx_sample s;
    float pdf_again, weight_importance;
};
GGX_TYPEDEF_STRUCT(ggx_stress_result)

GGX_INLINE ggx_stress_result ggx_stress_case(ggx_stress_input c)
{
    ggx_stress_result r;
#if GGX_DIELECTRIC
    r.s = ggx_sample_dielectric_method(GGX_METHOD, c.n, c.i, c.ax, c.ay, c.eta, 1, c.u1, c.u2, c.u3);
    r.weight_importance = ggx_sample_dielectric_method(GGX_METHOD, c.n, c.i, c.ax, c.ay, c.eta, 0, c.u1, c.u2, c.u3).weight;
    r.pdf_again = ggx_pdf_dielectric_method(GGX_METHOD, c.n, c.i, r.s.o, c.ax, c.ay, c.eta);
#else
    r.s = ggx_sample_method(GGX_METHOD, c.n, c.i, c.ax, c.ay, c.u1, c.u2);
    r.pdf_again = ggx_pdf_method(GGX_METHOD, c.n, c.i, r.s.o, c.ax, c.ay);
    r.weight_importance = 0.0f;
#endif
    return r;
}

// Output k of a case's result (k < GGX_STRESS_OUTPUTS).
GGX_INLINE float ggx_stress_output(ggx_stress_result r, ggx_uint k)
{
    const ggx_sample s = r.s;
    switch (k) {
    case 0u: return s.m.x;
    case 1u: return s.m.y;
    case 2u: return s.m.z;
    case 3u: return s.o.x;
    case 4u: return s.o.y;
    case 5u: return s.o.z;
    case 6u: return s.pdf_m;
    case 7u: return s.pdf_o;
    case 8u: return s.weight;
    case 9u: return r.pdf_again;
    default: return r.weight_importance;
    }
}

#endif
