// uniforms.hlsl - uniforms.comp in HLSL (uint64_t).
struct Request {
    uint seed_lo, seed_hi, first_lo, first_hi, count;
};
[[vk::push_constant]] ConstantBuffer<Request> request;  // glslang: a plain struct would go to $Global
[[vk::binding(0, 0)]] RWStructuredBuffer<float> values;

#include "uniforms_request.h"

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    ggx_test_uniforms(id.x);
}
