// caps_forward.glsl - the helper file caps_copy.glsl includes by relative
// path: caps through the device headers, taking an engine's vec2s.
#pragma once

ggx_sample caps_forward_sample(vec3 i, vec2 alpha, vec2 u)
{
    return ggx_sample_caps(i, alpha.x, alpha.y, u.x, u.y);
}

float caps_forward_pdf(vec3 i, vec3 o, vec2 alpha)
{
    return ggx_pdf_caps(i, o, alpha.x, alpha.y);
}
