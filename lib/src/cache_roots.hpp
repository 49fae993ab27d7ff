// cache_roots.hpp - where the library keeps files between processes: the
// copies of the device headers and the program binaries.
#pragma once

#include <filesystem>
#include <vector>

namespace ggxcl::detail {

// $XDG_CACHE_HOME/ggxcl or ~/.cache/ggxcl, then the temporary directory
// (with the user id, as several users share it); the first usable one wins.
std::vector<std::filesystem::path> cache_roots();

} // namespace ggxcl::detail
