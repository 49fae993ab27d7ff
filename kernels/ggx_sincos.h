// ggx_sincos.h - sine and cosine of the sampling angle 2 pi u, u in [0, 1).
// Build option GGX_FAST_SINCOS selects the form (the runtime's precision
// modes): 0 the built-in sin and cos (precise; out-of-line calls that PoCL
// cannot vectorize), 1 short polynomials that vectorize.
//
// Fast form: x = 2 pi (u - 1/2) lies in [-pi, pi), sin(2 pi u) = -sin(x) and
// cos(2 pi u) = -cos(x); sin(x) = x S(x^2) and cos(x) = C(x^2) with S of
// degree 5 and C of degree 6, Chebyshev fits on [0, pi^2] (near minimax).
// Maximum error against the exact sin(2 pi u), cos(2 pi u) over every u of
// the 24-bit grid: 6.4e-7 and 5.0e-7 (the float rounding floor; the precise
// path rounds 2 pi u to float first and is no better).
#ifndef GGX_SINCOS_H
#define GGX_SINCOS_H

#include "ggx_common.h"

#ifndef GGX_FAST_SINCOS
#define GGX_FAST_SINCOS 0
#endif

GGX_INLINE void ggx_sincos_2pi(float u, float* s, float* c)
{
#if GGX_FAST_SINCOS
    float x = GGX_TWO_PI * (u - 0.5f);
    float t = x * x;
    float ps = 2.708831159e-06f + t * -2.069813466e-08f;
    ps = -1.981763099e-04f + t * ps;
    ps = 8.332791503e-03f + t * ps;
    ps = -1.666662111e-01f + t * ps;
    ps = 9.999999378e-01f + t * ps;
    float pc = -2.707903082e-07f + t * 1.724509174e-09f;
    pc = 2.476988356e-05f + t * pc;
    pc = -1.388780360e-03f + t * pc;
    pc = 4.166648922e-02f + t * pc;
    pc = -4.999998910e-01f + t * pc;
    pc = 9.999999891e-01f + t * pc;
    *s = -x * ps;
    *c = -pc;
#else
    float phi = GGX_TWO_PI * u;
    *s = sin(phi);
    *c = cos(phi);
#endif
}

#endif
