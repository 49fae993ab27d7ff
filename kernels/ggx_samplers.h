// ggx_samplers.h - every ggxcl sampler and pdf, plus dispatchers by method
// id, for OpenCL C kernels, C++17 and CUDA alike (ggx_platform.h).  Include
// this one header to get all of them:
//   ggx_sample_<method>(...) -> ggx_sample {m, o, pdf_m, pdf_o, weight}
//   ggx_pdf_<method>(...)    -> pdf of o recomputed from (i, o) alone
//   ggx_eval_reflection(...)  -> the BRDF value f |cos| of any (i, o), for MIS (ggx_bsdf.h)
//   ggx_fresnel_*(...)        -> Fresnel terms; roughness conventions (ggx_fresnel.h)
// and, including this one, ggx_dielectric.h: every sampler on a rough
// dielectric (reflection or refraction), ggx_world.h: all of it in world space.
// Method ids: GGX_METHOD_* of ggx_contract.h (the C++ enum ggxcl::Method is
// made from the same list); an id that is none of them gives the fallback
// sample about n ("no sample", ggx_guards.h).
#ifndef GGX_SAMPLERS_H
#define GGX_SAMPLERS_H

#include "ggx_bsdf.h"
#include "ggx_contract.h"
#include "ggx_fresnel.h"
#include "ggx_philox.h"
#include "ggx_sample_bounded.h"
#include "ggx_sample_caps.h"
#include "ggx_sample_caps_iso.h"
#include "ggx_sample_heitz.h"
#include "ggx_sample_ndf.h"
#ifdef GGX_USER_SAMPLER
#include "ggx_user_sampler.h"
#endif

#include "ggx_method_traits.h"

// The dispatchers test each method of GGX_METHOD_LIST (ggx_contract.h) in
// turn and call its ggx_dispatch_* form (ggx_common.h); with a compile-time
// constant `method` the chain folds to one sampler.  Only caps-iso reads n
// (world space); the others work in tangent space.
#define GGX_SAMPLE_IF_METHOD(ID, identifier, name, paper, how, space, alpha, normals, dielectric, below, limits) \
    if (GGX_IS_METHOD(method, GGX_METHOD_##ID))     \
        return ggx_dispatch_sample_##identifier(n, i, ax, ay, u1, u2);
#define GGX_PDF_IF_METHOD(ID, identifier, name, paper, how, space, alpha, normals, dielectric, below, limits) \
    if (GGX_IS_METHOD(method, GGX_METHOD_##ID))     \
        return ggx_dispatch_pdf_##identifier(n, i, o, ax, ay);
// A program built with a user sampler (ggx_user_sampler.h) dispatches its id too.
#ifdef GGX_USER_SAMPLER
#define GGX_USER_METHOD_LINE(X) X(USER, user, "user", "your file", "your sampler", TANGENT, ANISOTROPIC, OWN, NO, YES, "")
#else
#define GGX_USER_METHOD_LINE(X)
#endif

GGX_INLINE ggx_sample ggx_sample_method(int method, ggx_vec3 n, ggx_vec3 i, ggx_real ax, ggx_real ay, ggx_real u1,
                                        ggx_real u2)
{
    GGX_METHOD_LIST(GGX_SAMPLE_IF_METHOD)
    GGX_USER_METHOD_LINE(GGX_SAMPLE_IF_METHOD)
    return ggx_fallback_sample(n);  // not a method id
}

GGX_INLINE ggx_real ggx_pdf_method(int method, ggx_vec3 n, ggx_vec3 i, ggx_vec3 o, ggx_real ax, ggx_real ay)
{
    GGX_METHOD_LIST(GGX_PDF_IF_METHOD)
    GGX_USER_METHOD_LINE(GGX_PDF_IF_METHOD)
    return GGX_R(0.0f);  // not a method id
}

#endif
