// sample.comp - a ggxcl sampler in a GLSL compute shader: the request's
// push constants and buffers, and sample_request.h's body per invocation.
#version 450
#extension GL_GOOGLE_include_directive : require

layout(local_size_x = 64) in;
layout(push_constant) uniform Request {
    float view_x, view_y, view_z, alpha_x, alpha_y, eta;
    int radiance;
    uint count;
} request;
layout(std430, set = 0, binding = 0) readonly buffer Uniforms { float uniforms[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Samples { float samples[]; };

#include "sample_request.h"

void main()
{
    ggx_test_sample(gl_GlobalInvocationID.x);
}
