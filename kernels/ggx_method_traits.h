// ggx_method_traits.h - the traits of GGX_METHOD_LIST (ggx_contract.h) as
// device functions of a method id, for the code that depends on them: each
// tests the methods of the list in turn (GGX_IS_METHOD, below), so
// with a compile-time id, or GGX_ONLY_METHOD, it folds to a constant.  An id
// outside the list (a user sampler's, GGX_METHOD_USER) has none of them:
// tangent space, no dielectric sampler, not the NDF.
#ifndef GGX_METHOD_TRAITS_H
#define GGX_METHOD_TRAITS_H

#include "ggx_contract.h"
#include "ggx_platform.h"

// GGX_ONLY_METHOD=<id>: the program uses that one method (the runtime's bulk
// kernels set it to GGX_METHOD).  The dispatchers then test constants and
// the compiler emits the one sampler alone: a driver that translates every
// branch before it folds the method id (Mesa rusticl) builds 3-4x faster.
#ifdef GGX_ONLY_METHOD
#if (GGX_ONLY_METHOD < 0 || GGX_ONLY_METHOD >= GGX_METHOD_COUNT) && \
    !(defined(GGX_USER_SAMPLER) && GGX_ONLY_METHOD == GGX_METHOD_USER)
#error "GGX_ONLY_METHOD: not a method id (GGX_METHOD_NDF .. GGX_METHOD_BOUNDED of ggx_contract.h)"
#endif
#define GGX_IS_METHOD(method, id) (GGX_ONLY_METHOD == (id))
#else
#define GGX_IS_METHOD(method, id) ((method) == (id))
#endif

#define GGX_IF_WORLD_SPACE(ID, identifier, name, paper, how, space, alpha, normals, dielectric, below, limits) \
    | (ggx_to_int(GGX_IS_METHOD(method, GGX_METHOD_##ID)) & GGX_SPACE_##space)
#define GGX_IF_DIELECTRIC(ID, identifier, name, paper, how, space, alpha, normals, dielectric, below, limits) \
    | (ggx_to_int(GGX_IS_METHOD(method, GGX_METHOD_##ID)) & GGX_TRAIT_##dielectric)
#define GGX_IF_NDF_NORMALS(ID, identifier, name, paper, how, space, alpha, normals, dielectric, below, limits) \
    | (ggx_to_int(GGX_IS_METHOD(method, GGX_METHOD_##ID)) & ggx_to_int(GGX_NORMALS_##normals == GGX_NORMALS_NDF))

// 1 when `method` works about the caller's world-space normal (caps-iso), 0 in tangent space.
GGX_INLINE int ggx_method_world_space(int method)
{
    return 0 GGX_METHOD_LIST(GGX_IF_WORLD_SPACE);
}

// 1 when `method` has a rough dielectric sampler (all but bounded).
GGX_INLINE int ggx_method_dielectric(int method)
{
    return 0 GGX_METHOD_LIST(GGX_IF_DIELECTRIC);
}

// 1 when `method`'s normals follow the NDF D(m) mz (ndf), 0 for the VNDF and densities of their own.
GGX_INLINE int ggx_method_ndf_normals(int method)
{
    return 0 GGX_METHOD_LIST(GGX_IF_NDF_NORMALS);
}

#undef GGX_IF_WORLD_SPACE
#undef GGX_IF_DIELECTRIC
#undef GGX_IF_NDF_NORMALS

#endif
