// kernel_sources.hpp - the OpenCL C sources of kernels/, embedded at build
// time with their includes expanded, so that an installed program needs no
// source tree and a user's own kernel can prepend the GGX device functions:
//   std::string src = ggxcl::kernel_source("ggx_samplers.h") + my_kernel;
#pragma once

#include <string>
#include <vector>

namespace ggxcl {

// Names of the embedded files ("ggx_bulk.cl", "ggx_samplers.h", ...).
std::vector<std::string> kernel_files();

// The expanded text of one embedded file (with #line markers); throws
// InvalidArgument naming the files that exist.
const std::string& kernel_source(const std::string& file);

} // namespace ggxcl
