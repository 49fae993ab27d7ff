// method.cpp - method names (from the one list of methods, ggx_contract.h) and parsing.
#include "ggxcl/method.hpp"

#include "device_contract.hpp"
#include "ggxcl/error.hpp"

namespace ggxcl {

std::string_view method_name(Method method)
{
    switch (method) {
#define GGXCL_METHOD_NAME(ID, identifier, name) \
    case Method::identifier: return name;
        GGX_METHOD_LIST(GGXCL_METHOD_NAME)
#undef GGXCL_METHOD_NAME
    }
    return "unknown";
}

Method parse_method(std::string_view name)
{
    for (Method method : all_methods)
        if (method_name(method) == name)
            return method;
    throw InvalidArgument("method", std::string(name), "one of " + method_list());
}

std::string method_list()
{
    std::string list;
    for (Method method : all_methods)
        list += (list.empty() ? "" : ", ") + std::string(method_name(method));
    return list;
}

bool samples_visible_normals(Method method)
{
    return method != Method::ndf;
}

} // namespace ggxcl
