// sample.comp - a ggxcl sampler in a GLSL compute shader: sample j of one
// request from the caller's uniforms (planes u1, u2, u3), stored as planes
// m (3), o (3), pdf_m, pdf_o, weight and the pdf of o that the method's pdf
// function recomputes from (i, o).  Built per method (GGX_TEST_METHOD, also
// GGX_ONLY_METHOD) and per kind: conductor, or dielectric (GGX_TEST_DIELECTRIC=1).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "ggx_world.h"

layout(local_size_x = 64) in;
layout(push_constant) uniform Request {
    float view_x, view_y, view_z, alpha_x, alpha_y, eta;
    int radiance;
    uint count;
} request;
layout(std430, set = 0, binding = 0) readonly buffer Uniforms { float uniforms[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Samples { float samples[]; };

void main()
{
    uint j = gl_GlobalInvocationID.x, n = request.count;
    if (j >= n)
        return;
    vec3 view = vec3(request.view_x, request.view_y, request.view_z), normal = vec3(0.0, 0.0, 1.0);
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
