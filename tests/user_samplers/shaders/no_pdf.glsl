// no_pdf.glsl - a negative control: a sample function and a claim, but no
// ggx_user_pdf; refused before any build, naming the file and the function.
#include "ggx_samplers.h"

#define GGX_USER_DISTRIBUTION GGX_USER_VNDF

ggx_sample ggx_user_sample(vec3 i, float ax, float ay, float u1, float u2)
{
    return ggx_sample_caps(i, ax, ay, u1, u2);
}
