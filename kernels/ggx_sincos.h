// ggx_sincos.h - sine and cosine of the sampling angle 2 pi u, u in [0, 1).
// The precise mode uses the built-in functions; faster variants are build
// options of the program (see the runtime's precision modes).
#ifndef GGX_SINCOS_H
#define GGX_SINCOS_H

#include "ggx_common.h"

GGX_INLINE void ggx_sincos_2pi(float u, float* s, float* c)
{
    float phi = GGX_TWO_PI * u;
    *s = sin(phi);
    *c = cos(phi);
}

#endif
