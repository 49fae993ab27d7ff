// sample_request.h - the body of the sample shaders, one text for GLSL
// (sample.comp) and HLSL (sample.hlsl): sample j of the request from the
// caller's uniforms (planes u1, u2, u3), stored as planes m (3), o (3),
// pdf_m, pdf_o, weight and the pdf of o that the method's pdf function
// recomputes from (i, o).  The including shader declares `request` (its
// push constants), `uniforms` and `samples` (storage buffers) first.
// Built per method (GGX_TEST_METHOD, also GGX_ONLY_METHOD) and per kind:
// conductor, or dielectric (GGX_TEST_DIELECTRIC=1).
#include "ggx_world.h"

void ggx_test_sample(uint j)
{
    uint n = request.count;
    if (j >= n)
        return;
    ggx_vec3 view = ggx_vec3_make(request.view_x, request.view_y, request.view_z);
    ggx_vec3 normal = ggx_vec3_make(0.0f, 0.0f, 1.0f);
    float ax = request.alpha_x, ay = request.alpha_y, u1 = uniforms[j], u2 = uniforms[n + j];
#if GGX_TEST_DIELECTRIC
    float u3 = uniforms[2 * n + j];
    ggx_sample s = ggx_sample_dielectric_method(GGX_TEST_METHOD, normal, view, ax, ay, request.eta,
                                                request.radiance, u1, u2, u3);
    float pdf = ggx_pdf_dielectric_method(GGX_TEST_METHOD, normal, view, s.o, ax, ay, request.eta);
#else
    ggx_sample s = ggx_sample_method(GGX_TEST_METHOD, normal, view, ax, ay, u1, u2);
    float pdf = ggx_pdf_method(GGX_TEST_METHOD, normal, view, s.o, ax, ay);
#endif
    samples[j] = s.m.x;
    samples[n + j] = s.m.y;
    samples[2 * n + j] = s.m.z;
    samples[3 * n + j] = s.o.x;
    samples[4 * n + j] = s.o.y;
    samples[5 * n + j] = s.o.z;
    samples[6 * n + j] = s.pdf_m;
    samples[7 * n + j] = s.pdf_o;
    samples[8 * n + j] = s.weight;
    samples[9 * n + j] = pdf;
}
