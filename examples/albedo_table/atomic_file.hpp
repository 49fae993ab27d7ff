// atomic_file.hpp - writing a file under a temporary name and renaming it
// at the end, so a reader never sees a partial file and a failure leaves
// none behind.
#pragma once

#include <functional>
#include <string>

namespace albedo {

// Calls write(temporary path), which returns false on failure, then renames
// the temporary to `path`; throws std::runtime_error naming `path` on failure.
void write_atomically(const std::string& path, const std::function<bool(const std::string&)>& write);

} // namespace albedo
