// binary_cache.hpp - program binaries kept on disk between processes, so a
// program variant is compiled once per machine and driver, not once per
// process (Mesa rusticl, for one, keeps none itself: 1-4 s per variant).
//
// A binary is stored under a key naming everything it depends on: the
// library version, the platform and device with their versions and driver
// version, the build options and the whole source; a file is used only when
// its stored key equals the key asked for and its bytes match their stored
// checksum.  GGXCL_PROGRAM_CACHE chooses the directory (for every platform)
// or turns the cache off ("off"); unset, the cache is programs/ under the
// library's cache root, for platforms that keep no programs themselves.  The directory is kept under 512 MiB by
// removing the least recently written files.
#pragma once

#include <string>
#include <vector>

#include "ggxcl/opencl.hpp"

namespace ggxcl::detail {

// Whether programs for `device` go through the cache (see above).
bool binary_cache_applies(const cl::Device& device);

std::string binary_cache_key(const cl::Device& device, const std::string& source, const std::string& options);

// The stored binary of `key`; false when there is none (or the cache is off).
bool load_program_binary(const std::string& key, std::vector<unsigned char>& binary);

// Stores the binary of `key` (written to a temporary file, then renamed);
// a cache that cannot be written is skipped silently.
void store_program_binary(const std::string& key, const std::vector<unsigned char>& binary);

} // namespace ggxcl::detail
