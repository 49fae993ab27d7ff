// method.hpp - the six sampling methods and their names, the same in the
// API, the CLI and the docs.
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace ggxcl {

// The numeric values are the kernels' method ids: the list of methods in the
// device header ggx_contract.h gives each its id, enumerator and name, and
// the library does not build when this enum or all_methods differs from it.
enum class Method {
    ndf = 0,       // Walter et al. 2007: sample D(m) mz
    heitz = 1,     // Heitz 2018: exact VNDF, warped disk
    heitz2017 = 2, // Heitz 2017 report: exact VNDF, two half disks
    caps = 3,      // Dupuy & Benyoub 2023: spherical caps
    caps_iso = 4,  // Benyoub 2024: isotropic, world space, no basis
    bounded = 5,   // Eto & Tokuyoshi 2023: bounded VNDF for reflections
};

inline constexpr std::array<Method, 6> all_methods = {
    Method::ndf, Method::heitz, Method::heitz2017, Method::caps, Method::caps_iso, Method::bounded};

// "ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded".
std::string_view method_name(Method method);

// The method of a name; throws InvalidArgument naming the allowed names.
Method parse_method(std::string_view name);

// "ndf, heitz, heitz2017, caps, caps-iso, bounded", for messages.
std::string method_list();

// True for the methods that sample visible normals (all but ndf).
bool samples_visible_normals(Method method);

} // namespace ggxcl
