// embedded_text.hpp - a file the tool carries inside itself (a table made
// by tools/embed_kernels.cpp: the plotting scripts, the pages' style and
// script), looked up by name.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace ggxapp {

// The text of `name` in a generated table of `count` entries {name, text}.
template <class Source>
const char* embedded_text(const Source* table, std::size_t count, const std::string& name)
{
    for (std::size_t k = 0; k < count; ++k)
        if (name == table[k].name)
            return table[k].text;
    throw std::logic_error("nothing embedded under the name " + name);
}

} // namespace ggxapp
