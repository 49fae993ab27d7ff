// embedded_sources.hpp - the table of scripts that tools/embed_kernels.cpp
// generates for the app (the plotting script), so `ggx` needs no source tree.
#pragma once

#include <cstddef>

namespace ggxapp::detail {

struct EmbeddedSource {
    const char* name;
    const char* text;
};

extern const EmbeddedSource embedded_sources[];
extern const std::size_t embedded_source_count;

} // namespace ggxapp::detail
