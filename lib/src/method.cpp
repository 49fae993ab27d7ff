// method.cpp - method names (from the one list of methods, ggx_contract.h) and parsing.
#include "ggxcl/method.hpp"

#include "named_values.hpp"

namespace ggxcl {

std::string_view method_name(Method method)
{
    switch (method) {
#define GGXCL_METHOD_NAME(ID, identifier, name) \
    case Method::identifier: return name;
        GGX_METHOD_LIST(GGXCL_METHOD_NAME)
#undef GGXCL_METHOD_NAME
    case Method::user: return "user";
    }
    return "unknown";
}

Method parse_method(std::string_view name)
{
    return detail::parse_named(name, all_methods, method_name, "method");
}

std::string method_list()
{
    return detail::name_list(all_methods, method_name);
}

bool samples_visible_normals(Method method)
{
    return method != Method::ndf;
}

} // namespace ggxcl
