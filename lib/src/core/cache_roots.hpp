// cache_roots.hpp - where the library keeps files between processes (the
// copies of the device headers and the program binaries), and the 64-bit
// FNV-1a hash both name and check their files with.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace ggxcl::detail {

// $XDG_CACHE_HOME/ggxcl or ~/.cache/ggxcl, then the temporary directory
// (with the user id, as several users share it); the first usable one wins.
std::vector<std::filesystem::path> cache_roots();

// FNV-1a over `bytes`, continuing from `hash` (default: the offset basis).
template <typename Bytes>
std::uint64_t fnv1a(const Bytes& bytes, std::uint64_t hash = 14695981039346656037ull)
{
    for (unsigned char c : bytes)
        hash = (hash ^ c) * 1099511628211ull;
    return hash;
}

} // namespace ggxcl::detail
