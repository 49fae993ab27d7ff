// named_values.hpp - an enum's values by name: the list of names for
// messages ("a, b, c") and the value of a name, refused with
// InvalidArgument naming the parameter and the allowed names.  What
// parse_method, parse_precision and parse_sequence share.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "ggxcl/error.hpp"

namespace ggxcl::detail {

template <class Value, std::size_t N, class NameOf>
std::string name_list(const std::array<Value, N>& all, NameOf name_of)
{
    std::string list;
    for (Value value : all)
        list += (list.empty() ? "" : ", ") + std::string(name_of(value));
    return list;
}

template <class Value, std::size_t N, class NameOf>
Value parse_named(std::string_view name, const std::array<Value, N>& all, NameOf name_of, const char* parameter)
{
    for (Value value : all)
        if (name_of(value) == name)
            return value;
    throw InvalidArgument(parameter, std::string(name), "one of " + name_list(all, name_of));
}

} // namespace ggxcl::detail
