// embedded_sources.hpp - the table that tools/embed_kernels.cpp generates.
#pragma once

#include <cstddef>

namespace ggxcl::detail {

struct EmbeddedSource {
    const char* name;
    const char* text;
};

extern const EmbeddedSource embedded_sources[];
extern const std::size_t embedded_source_count;

} // namespace ggxcl::detail
