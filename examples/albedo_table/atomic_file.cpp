// atomic_file.cpp - temporary name, then rename.
#include "atomic_file.hpp"

#include <cstdio>
#include <stdexcept>
#include <unistd.h>

namespace albedo {

void write_atomically(const std::string& path, const std::function<bool(const std::string&)>& write)
{
    const std::string temporary = path + ".tmp" + std::to_string(getpid());
    if (!write(temporary) || std::rename(temporary.c_str(), path.c_str()) != 0) {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write " + path);
    }
}

} // namespace albedo
