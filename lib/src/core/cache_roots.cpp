// cache_roots.cpp - the per-user cache directories of the library.
#include "cache_roots.hpp"

#include <cstdlib>
#include <string>
#include <unistd.h>

namespace ggxcl::detail {

namespace fs = std::filesystem;

std::vector<fs::path> cache_roots()
{
    std::vector<fs::path> roots;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        roots.push_back(fs::path(xdg) / "ggxcl");
    else if (const char* home = std::getenv("HOME"); home && *home)
        roots.push_back(fs::path(home) / ".cache" / "ggxcl");
    std::error_code no_tmp;
    fs::path tmp = fs::temp_directory_path(no_tmp);
    if (!no_tmp)
        roots.push_back(tmp / ("ggxcl-" + std::to_string(getuid())));
    return roots;
}

} // namespace ggxcl::detail
