// build_program.hpp - building an OpenCL program from source, with the
// errors of the library: ClError when the program cannot be created,
// BuildError (CL error name, options, build log) when it does not build.
#pragma once

#include <string>

#include "ggxcl/opencl.hpp"

namespace ggxcl::detail {

cl::Program build_program(const cl::Context& context, const cl::Device& device, const std::string& source,
                          const std::string& options);

} // namespace ggxcl::detail
