// ggx_user_sampler.h - the functions a user sampler's file defines, and the
// dispatch of method id GGX_METHOD_USER to them.  The runtime builds a
// program with a user sampler as its kernel file followed by the user's file
// (its includes expanded) with -DGGX_USER_SAMPLER=1 and
// -DGGX_USER_SAMPLES_M=0|1, so the kernels see the declarations below and
// the definitions come after them.  The user's file defines, in tangent
// space (n = +z, i unit with iz > 0 for the views a renderer sees):
//   either ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2)
//          -> m, o, pdf_m, pdf_o and weight = f |oz| / pdf_o (Fresnel 1)
//   or     ggx_vec3 ggx_user_sample_m(ggx_vec3 i, float ax, float ay, float u1, float u2)
//          -> the unit normal m alone; o = reflect(i, m), pdf_o = ggx_user_pdf(i, o),
//             pdf_m = 4 |i.m| pdf_o and the weight follow (ggx_user_complete)
//   and    float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay)
//          -> the density of o per steradian, recomputed from (i, o) alone
// and states the distribution it claims with
//   #define GGX_USER_DISTRIBUTION GGX_USER_VNDF   (or GGX_USER_NDF, GGX_USER_OWN)
// It may include any device header ("ggx_samplers.h" gives all of them).
// docs/USER-SAMPLERS.md tells the whole contract.
#ifndef GGX_USER_SAMPLER_H
#define GGX_USER_SAMPLER_H

#include "ggx_bsdf.h"
#include "ggx_contract.h"

#ifndef GGX_USER_SAMPLES_M
#define GGX_USER_SAMPLES_M 0
#endif

#if GGX_USER_SAMPLES_M
GGX_INLINE ggx_vec3 ggx_user_sample_m(ggx_vec3 i, float ax, float ay, float u1, float u2);
#else
GGX_INLINE ggx_sample ggx_user_sample(ggx_vec3 i, float ax, float ay, float u1, float u2);
#endif
GGX_INLINE float ggx_user_pdf(ggx_vec3 i, ggx_vec3 o, float ax, float ay);

// The sample of a user's normal m: m normalized where its squared length is
// off 1 by more than 1e-5 (an fp16 normal; a unit float normal is left as it
// is), the mirror direction o = 2 (i.m) m - i, its density from the user's
// pdf, the density of m through the reflection's Jacobian |do/dm| = 4 |i.m|
// (Walter et al. 2007, eq. 14), and the weight f |oz| / pdf_o with the BRDF
// of ggx_bsdf.h (0 where pdf_o is 0).
GGX_INLINE ggx_sample ggx_user_complete(ggx_vec3 i, ggx_vec3 m, float ax, float ay)
{
    const float length2 = ggx_dot(m, m);
    m = ggx_fabs(length2 - 1.0f) > 1e-5f ? ggx_normalize(m) : m;
    ggx_sample s;
    s.m = m;
    s.o = ggx_reflect(i, m);
    s.pdf_o = ggx_user_pdf(i, s.o, ax, ay);
    s.pdf_m = 4.0f * ggx_fabs(ggx_dot(i, m)) * s.pdf_o;
    s.weight = s.pdf_o > 0.0f ? ggx_eval_reflection(i, s.o, ax, ay) / s.pdf_o : 0.0f;
    return s;
}

GGX_INLINE ggx_sample ggx_dispatch_sample_user(ggx_vec3 n, ggx_vec3 i, float ax, float ay, float u1, float u2)
{
    GGX_UNUSED(n);
#if GGX_USER_SAMPLES_M
    return ggx_user_complete(i, ggx_user_sample_m(i, ax, ay, u1, u2), ax, ay);
#else
    return ggx_user_sample(i, ax, ay, u1, u2);
#endif
}

GGX_INLINE float ggx_dispatch_pdf_user(ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, float ax, float ay)
{
    GGX_UNUSED(n);
    return ggx_user_pdf(i, o, ax, ay);
}

#endif
