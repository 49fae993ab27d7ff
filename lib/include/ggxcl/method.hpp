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
// method ids (GGX_METHOD_*).
enum class Method { GGX_METHOD_LIST(GGX_METHOD_ENUMERATOR) };

#define GGX_METHOD_ENUM Method
inline constexpr std::array<Method, GGX_METHOD_COUNT> all_methods = {GGX_METHOD_LIST(GGX_METHOD_ENUMERATOR_OF)};
#undef GGX_METHOD_ENUM

// "ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded".
std::string_view method_name(Method method);

// The method of a name; throws InvalidArgument naming the allowed names.
Method parse_method(std::string_view name);

// "ndf, heitz, heitz2017, caps, caps-iso, bounded", for messages.
std::string method_list();

// True for the methods that sample visible normals (all but ndf).
bool samples_visible_normals(Method method);

} // namespace ggxcl
