// fp16_inside.glsl - a GLSL sampler with a float interface that computes in
// half precision inside, as engines write samplers for mobile GPUs: caps'
// visible normal (a uniform point on the cap above the stretched view's
// plane, plus that view, stretched back) with every operation in
// float16_t, the pdf in float.  Its SPIR-V needs the device's
// shaderFloat16, which ggxcl enables where the device has it.
#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

vec3 ggx_user_sample_m(vec3 i, float ax, float ay, float u1, float u2)
{
    const float16_t one = float16_t(1.0), hx = float16_t(ax), hy = float16_t(ay);
    const f16vec3 v = normalize(f16vec3(hx * float16_t(i.x), hy * float16_t(i.y), float16_t(i.z)));
    const float16_t z = one - float16_t(u1) * (one + v.z);
    const float16_t r = sqrt(max(float16_t(0.0), one - z * z));
    const float16_t phi = float16_t(6.2831853) * float16_t(u2);
    const f16vec3 h = f16vec3(r * cos(phi), r * sin(phi), z) + v;
    return normalize(vec3(f16vec3(hx * h.x, hy * h.y, h.z)));
}

float ggx_user_pdf(vec3 i, vec3 o, float ax, float ay)
{
    return ggx_pdf_caps(i, o, ax, ay);
}
