// uniforms.comp - the uniforms of ggx_philox.h and ggx_sobol.h in a GLSL
// compute shader (uniforms_request.h's body per invocation).
#version 450
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 64) in;
layout(push_constant) uniform Request {
    uint seed_lo, seed_hi, first_lo, first_hi, count;
} request;
layout(std430, set = 0, binding = 0) writeonly buffer Values { float values[]; };

#include "uniforms_request.h"

void main()
{
    ggx_test_uniforms(gl_GlobalInvocationID.x);
}
