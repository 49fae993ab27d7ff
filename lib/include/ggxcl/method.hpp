// method.hpp - the sampling methods, their names and their traits, the same
// in the API, the CLI, Python, the device headers and the docs: made from the
// project's one table of methods, GGX_METHOD_LIST of the device header
// ggx_contract.h (installed as <ggxcl/cl/ggx_contract.h>).  Every rule that
// depends on what a method is (its space, isotropic only, dielectric, ...)
// reads method_traits; none compares with a named method.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "ggxcl/cl/ggx_contract.h"

namespace ggxcl {

// ndf, heitz, heitz2017, caps, caps_iso, bounded; the values are the kernels'
// method ids (GGX_METHOD_*).  `user` is a sampler of the user's own
// (SampleParams::user_sampler, ggxcl/user_sampler.hpp), id GGX_METHOD_USER:
// no list of built-in methods (all_methods, method_table, method_list) holds it.
enum class Method { GGX_METHOD_LIST(GGX_METHOD_ENUMERATOR) user = GGX_METHOD_USER };

#define GGX_METHOD_ENUM Method
inline constexpr std::array<Method, GGX_METHOD_COUNT> all_methods = {GGX_METHOD_LIST(GGX_METHOD_ENUMERATOR_OF)};
#undef GGX_METHOD_ENUM

// Where a method works (GGX_SPACE_*): tangent - about +z (the library
// transforms world-space requests, SampleParams::world_space); world - about
// the caller's world-space normal (SampleParams::normal).
enum class Space { tangent = GGX_SPACE_TANGENT, world = GGX_SPACE_WORLD };
std::string_view space_name(Space space);  // "tangent", "world"

// The distribution of the sampled normals (GGX_NORMALS_*):
//   vndf - the GGX visible normals, D_i(m) = G1(i) max(0, i.m) D(m) / iz (as heitz, caps);
//   ndf  - the GGX normals, D(m) mz (as ndf);
//   own  - a density of the method's own, given by its pdf alone (as bounded).
// A user sampler claims one (GGX_USER_DISTRIBUTION, UserSampler::distribution).
enum class Distribution { vndf = GGX_NORMALS_VNDF, ndf = GGX_NORMALS_NDF, own = GGX_NORMALS_OWN };
inline constexpr std::array<Distribution, 3> all_distributions = {Distribution::vndf, Distribution::ndf,
                                                                  Distribution::own};
std::string_view distribution_name(Distribution distribution);  // "vndf", "ndf", "own"

// What a method is: one row of GGX_METHOD_LIST (its comment defines each trait).
struct MethodTraits {
    Method method;
    std::string_view name;    // what users type: "caps-iso"
    std::string_view paper;   // "Benyoub 2024, VNDF importance sampling for ..."
    std::string_view how;     // what it does, in a line
    Space space;
    bool isotropic_only;      // alpha_x == alpha_y only
    Distribution normals;     // what the sampled normals follow
    bool dielectric;          // has a rough dielectric sampler (eta != 0)
    bool views_below;         // correct for views below the horizon
    std::string_view limits;  // why a trait above is missing, for messages ("" when none is)
};

#define GGXCL_METHOD_TRAITS_ROW(ID, identifier, name, paper, how, space, alpha, normals, dielectric, below, limits) \
    MethodTraits{Method::identifier,                                                                        \
                 name,                                                                                      \
                 paper,                                                                                     \
                 how,                                                                                       \
                 Space(GGX_SPACE_##space),                                                                  \
                 GGX_ALPHA_##alpha == GGX_ALPHA_ISOTROPIC,                                                  \
                 Distribution(GGX_NORMALS_##normals),                                                       \
                 GGX_TRAIT_##dielectric == GGX_TRAIT_YES,                                                   \
                 GGX_TRAIT_##below == GGX_TRAIT_YES,                                                        \
                 limits},
// The built-in methods' rows, in id order.
inline constexpr std::array<MethodTraits, GGX_METHOD_COUNT> method_table = {
    GGX_METHOD_LIST(GGXCL_METHOD_TRAITS_ROW)};
#undef GGXCL_METHOD_TRAITS_ROW

// The row of `method`.  Method::user's: tangent space, any alpha, conductors
// only, normals `own` (the file states its own claim: UserSampler::distribution).
const MethodTraits& method_traits(Method method);

// "ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded" ("user" for Method::user).
std::string_view method_name(Method method);

// The method of a name; throws InvalidArgument naming the allowed names.
Method parse_method(std::string_view name);

// "ndf, heitz, heitz2017, caps, caps-iso, bounded", for messages.
std::string method_list();

} // namespace ggxcl
