// ggx_sincos.h - sine and cosine of the sampling angle 2 pi u, u in [0, 1]:
// an exact reduction in u and two short polynomials, straight-line code
// that vectorizes (the built-in sin and cos are out-of-line calls that PoCL
// cannot vectorize).
//
// Reduction: q = 4u is exact, j = rint(q) the nearest quarter turn and
// f = q - j in [-1/2, 1/2] is exact too (Sterbenz), so 2 pi u = j pi/2 +
// (pi/2) f with no rounding at all.  sin((pi/2) f) = f S(f^2) and
// cos((pi/2) f) = 1 + f^2 C(f^2), S of degree 3 and C of degree 3, near-
// minimax fits on f^2 in [0, 1/4] with float coefficients tuned over the
// grid; S's constant term pi/2 is split into a float and its remainder.
// The quarter turns j mod 4 swap and negate the pair.
//
// Maximum error against the exact sin(2 pi u), cos(2 pi u), every u of the
// generator's 24-bit grid (tests/samplers/test_sincos.cpp checks it exhaustively):
// 0.86 ulp with fused multiply-adds; 1.6 ulp with -DGGX_NO_FMA=1 (a * b + c
// instead: the runtime sets it for devices without hardware fma).  Quarter
// turns are exact (sin(pi) = 0, cos(pi/2) = 0).  In half (GGX_ARITHMETIC 16) the same reduction with
// polynomials of its own (below): 1.12 x 2^-11 at most over every half u (tests/host/test_half_math.cpp).
#ifndef GGX_SINCOS_H
#define GGX_SINCOS_H

#include "ggx_common.h"

// A sine and a cosine (a struct: the shading languages have no pointers).
struct ggx_sin_cos {
    ggx_real sine, cosine;
};
GGX_TYPEDEF_STRUCT(ggx_sin_cos)

#if GGX_ARITHMETIC == 16
// sin((pi/2) f) and cos((pi/2) f) for |f| <= 1/2 in half: Taylor polynomials of degree 5 and 6 (the
// next terms are below 0.1 half ulp), pi/2 split into its half 1.5703125 and the remainder 4.838e-4,
// a normal half (float's remainder, 4.4e-8, is not).
GGX_INLINE ggx_sin_cos ggx_sincos_quarter(ggx_real f)
{
    ggx_real x = f * f;
    ggx_real ps = GGX_FMA(GGX_FMA(GGX_R(7.969262625e-02f), x, GGX_R(-6.459640975e-01f)), x,
                          GGX_R(4.838267949e-04f));  // the remainder of pi/2 - 1.5703125
    ggx_real pc = GGX_FMA(GGX_FMA(GGX_R(-2.086348076e-02f), x, GGX_R(2.536695079e-01f)), x,
                          GGX_R(-1.233700550e+00f));
    ggx_sin_cos result;
    result.sine = GGX_FMA(f, GGX_R(1.5703125f), f * ps);
    result.cosine = GGX_FMA(pc, x, GGX_R(1.0f));
    return result;
}
#else
// sin((pi/2) f) and cos((pi/2) f) for |f| <= 1/2.
GGX_INLINE ggx_sin_cos ggx_sincos_quarter(float f)
{
    float x = f * f;
    float ps = GGX_FMA(GGX_FMA(-4.602149129e-03f, x, 7.968020439e-02f), x, -6.459634900e-01f);
    ps = GGX_FMA(x, ps, -4.371138829e-08f);                     // the remainder of pi/2 - 1.5707964f
    float pc = GGX_FMA(GGX_FMA(GGX_FMA(9.067399078e-04f, x, -2.086152695e-02f), x, 2.536692619e-01f), x,
                       -1.233700514e+00f);
    ggx_sin_cos result;
    result.sine = GGX_FMA(f, 1.570796371e+00f, f * ps);
    result.cosine = GGX_FMA(pc, x, 1.0f);
    return result;
}
#endif

// sin(2 pi u) and cos(2 pi u).
GGX_INLINE ggx_sin_cos ggx_sincos_2pi(ggx_real u)
{
    ggx_real q = GGX_R(4.0f) * u;
    ggx_real j = ggx_rint(q);
    ggx_sin_cos part = ggx_sincos_quarter(q - j);
    int quarter = ggx_to_int(j);
    // Turning by a quarter maps (sin, cos) to (cos, -sin): odd quarters swap
    // the pair, quarters 2 and 3 negate the sine, 1 and 2 the cosine.
    ggx_real s_turned = (quarter & 1) != 0 ? part.cosine : part.sine;
    ggx_real c_turned = (quarter & 1) != 0 ? part.sine : part.cosine;
    ggx_sin_cos result;
    result.sine = (quarter & 2) != 0 ? -s_turned : s_turned;
    result.cosine = ((quarter + 1) & 2) != 0 ? -c_turned : c_turned;
    return result;
}

#endif
