// kernel_sources.cpp - lookup of the embedded kernel sources.
#include "ggxcl/kernel_sources.hpp"

#include <map>

#include "embedded_sources.hpp"
#include "ggxcl/error.hpp"

namespace ggxcl {

namespace {
const std::map<std::string, std::string>& source_table()
{
    static const std::map<std::string, std::string> table = [] {
        std::map<std::string, std::string> t;
        for (std::size_t k = 0; k < detail::embedded_source_count; ++k)
            t.emplace(detail::embedded_sources[k].name, detail::embedded_sources[k].text);
        return t;
    }();
    return table;
}
} // namespace

std::vector<std::string> kernel_files()
{
    std::vector<std::string> names;
    for (const auto& entry : source_table())
        names.push_back(entry.first);
    return names;
}

const std::string& kernel_source(const std::string& file)
{
    auto found = source_table().find(file);
    if (found == source_table().end()) {
        std::string names;
        for (const std::string& name : kernel_files())
            names += (names.empty() ? "" : ", ") + name;
        throw InvalidArgument("kernel file", file, "one of " + names);
    }
    return found->second;
}

} // namespace ggxcl
