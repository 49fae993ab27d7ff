// header_roles.hpp - which device headers of kernels/ a language test compiles
// alone. One rule for every test: a header named *_shader.h is GLSL and HLSL
// alone (ggx_platform.h includes ggx_platform_shader.h there, the bulk and
// histogram shaders include their bodies); the kernel-only headers below are
// OpenCL C alone or need a kernel's build switches (GGX_METHOD, GGX_BINS_*).
#pragma once

#include <algorithm>
#include <array>
#include <string>

namespace ggxtest {

inline bool ends_with(const std::string& text, const std::string& tail)
{
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// A header included only by compute shaders (GLSL, HLSL).
inline bool is_shader_only_header(const std::string& file) { return ends_with(file, "_shader.h"); }

// A header included only by the bulk kernels and shaders, built with their switches.
inline bool is_kernel_only_header(const std::string& file)
{
    static const std::array<const char*, 5> names = {"ggx_kernel_io.h", "ggx_bulk_params.h", "ggx_bulk_sample.h",
                                                     "ggx_histogram_bin.h", "ggx_stress_case.h"};
    return std::find(names.begin(), names.end(), file) != names.end();
}

}  // namespace ggxtest
