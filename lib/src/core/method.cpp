// method.cpp - method names and traits (from the one table of methods,
// ggx_contract.h's GGX_METHOD_LIST), and parsing.
#include "ggxcl/method.hpp"

#include "named_values.hpp"

namespace ggxcl {

namespace {

constexpr MethodTraits user_traits{Method::user, "user", "your file", "your sampler", Space::tangent, false, Distribution::own,
                                   false, true, "a user sampler's reflection sampler runs on conductors only, in tangent space"};
// What method_traits gives a value that is no method (a cast of a bad id): no trait, named "unknown".
constexpr MethodTraits unknown_traits{Method::user, "unknown", "", "", Space::tangent, true, Distribution::own,
                                      false, false, "not a method"};

// The table holds the methods in id order.
constexpr bool table_in_id_order()
{
    for (std::size_t k = 0; k < method_table.size(); ++k)
        if (method_table[k].method != all_methods[k] || int(all_methods[k]) != int(k))
            return false;
    return true;
}
static_assert(table_in_id_order());

} // namespace

const MethodTraits& method_traits(Method method)
{
    const auto id = static_cast<std::size_t>(method);
    if (id < method_table.size())
        return method_table[id];
    return method == Method::user ? user_traits : unknown_traits;
}

std::string_view method_name(Method method)
{
    return method_traits(method).name;
}

Method parse_method(std::string_view name)
{
    return detail::parse_named(name, all_methods, method_name, "method");
}

std::string method_list()
{
    return detail::name_list(all_methods, method_name);
}

std::string_view space_name(Space space)
{
    return space == Space::world ? "world" : "tangent";
}

std::string_view distribution_name(Distribution distribution)
{
    switch (distribution) {
    case Distribution::vndf: return "vndf";
    case Distribution::ndf: return "ndf";
    case Distribution::own: return "own";
    }
    return "unknown";
}

} // namespace ggxcl
