// sample.hlsl - sample.comp in HLSL: the same request, uniforms and planes.
#include "ggx_world.h"

struct Request {
    float view_x, view_y, view_z, alpha_x, alpha_y, eta;
    int radiance;
    uint count;
};
[[vk::push_constant]] Request request;
[[vk::binding(0, 0)]] RWStructuredBuffer<float> uniforms;
[[vk::binding(1, 0)]] RWStructuredBuffer<float> samples;

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    uint j = id.x, n = request.count;
    if (j >= n)
        return;
    float3 view = float3(request.view_x, request.view_y, request.view_z), normal = float3(0.0f, 0.0f, 1.0f);
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
