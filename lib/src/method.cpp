// method.cpp - method names and parsing.
#include "ggxcl/method.hpp"

#include "ggxcl/error.hpp"

namespace ggxcl {

std::string_view method_name(Method method)
{
    switch (method) {
    case Method::ndf: return "ndf";
    case Method::heitz: return "heitz";
    case Method::heitz2017: return "heitz2017";
    case Method::caps: return "caps";
    case Method::caps_iso: return "caps-iso";
    case Method::bounded: return "bounded";
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
