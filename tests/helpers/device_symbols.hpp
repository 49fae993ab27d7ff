// device_symbols.hpp - the names an OpenCL C source defines at file scope
// (macros, functions, typedef names, struct/union/enum tags, enumerators
// and variables), read with a small tokenizer: what the device headers add
// to every user kernel that includes them, so each must carry the ggx_ /
// GGX_ prefix.
#pragma once

#include <string>
#include <vector>

namespace ggxtest {

// Every file-scope name `source` defines, in order of appearance.
std::vector<std::string> defined_names(const std::string& source);

// Those names that start with neither "ggx_" nor "GGX_".
std::vector<std::string> unprefixed_names(const std::string& source);

} // namespace ggxtest
