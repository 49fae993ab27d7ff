// version.hpp - the library version string.
#pragma once

namespace ggxcl {
const char* version();
}
