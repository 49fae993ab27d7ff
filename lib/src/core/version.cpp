// version.cpp - the library version, set by CMake from project(VERSION).
#include "ggxcl/version.hpp"

namespace ggxcl {
const char* version()
{
    return GGXCL_VERSION;
}
} // namespace ggxcl
