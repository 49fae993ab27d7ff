// sample.hlsl - sample.comp in HLSL: the same push constants and buffers,
// the same body (sample_request.h).
struct Request {
    float view_x, view_y, view_z, alpha_x, alpha_y, eta;
    int radiance;
    uint count;
};
[[vk::push_constant]] ConstantBuffer<Request> request;  // glslang: a plain struct would go to $Global
[[vk::binding(0, 0)]] RWStructuredBuffer<float> uniforms;
[[vk::binding(1, 0)]] RWStructuredBuffer<float> samples;

#include "sample_request.h"

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    ggx_test_sample(id.x);
}
