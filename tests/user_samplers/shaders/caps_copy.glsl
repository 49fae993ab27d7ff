// caps_copy.glsl - a GLSL user sampler that is caps, in a shader's own
// style (vec3, its helpers in a file of its own by relative path): every
// Vulkan front end must give caps' bits with it.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "ggx_samplers.h"
#include "helpers/caps_forward.glsl"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

ggx_sample ggx_user_sample(vec3 i, float ax, float ay, float u1, float u2)
{
    return caps_forward_sample(i, vec2(ax, ay), vec2(u1, u2));
}

float ggx_user_pdf(vec3 i, vec3 o, float ax, float ay)
{
    return caps_forward_pdf(i, o, vec2(ax, ay));
}
