// method.hpp - the sampling methods and their names, the same in the API,
// the CLI, the device headers and the docs: made from the project's one list
// of methods, GGX_METHOD_LIST of the device header ggx_contract.h (installed
// as <ggxcl/cl/ggx_contract.h>), which says what each method is.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "ggxcl/cl/ggx_contract.h"

namespace ggxcl {

// ndf, heitz, heitz2017, caps, caps_iso, bounded; the values are the kernels'
// method ids (GGX_METHOD_*).  `user` is a sampler of the user's own
// (SampleParams::user_sampler, ggxcl/user_sampler.hpp), id GGX_METHOD_USER:
// no list of built-in methods (all_methods, method_list) holds it.
enum class Method { GGX_METHOD_LIST(GGX_METHOD_ENUMERATOR) user = GGX_METHOD_USER };

#define GGX_METHOD_ENUM Method
inline constexpr std::array<Method, GGX_METHOD_COUNT> all_methods = {GGX_METHOD_LIST(GGX_METHOD_ENUMERATOR_OF)};
#undef GGX_METHOD_ENUM

// "ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded" ("user" for Method::user).
std::string_view method_name(Method method);

// The method of a name; throws InvalidArgument naming the allowed names.
Method parse_method(std::string_view name);

// "ndf, heitz, heitz2017, caps, caps-iso, bounded", for messages.
std::string method_list();

// True for the built-in methods that sample visible normals (all but ndf).
bool samples_visible_normals(Method method);

} // namespace ggxcl
