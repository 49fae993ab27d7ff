// build_program.hpp - building an OpenCL program from source, with the
// errors of the library: ClError when the program cannot be created,
// BuildError (CL error name, options, build log) when it does not build,
// the log's locations mapped back to the files of the source's #line
// markers whatever the compiler prints (build_log_lines.hpp).
// Every build gets the device's quirk options (device_quirks.hpp).
#pragma once

#include <string>

#include "ggxcl/opencl.hpp"

namespace ggxcl::detail {

// With `keep_binary` (for self-contained sources only: the key does not see
// files a source includes), the binary is loaded from and stored in the
// on-disk cache of binary_cache.hpp; a stored binary that the driver
// refuses is replaced by a build from source.  `from_binary`, when given,
// tells whether the program came from the cache.
cl::Program build_program(const cl::Context& context, const cl::Device& device, const std::string& source,
                          const std::string& options, bool keep_binary = false, bool* from_binary = nullptr);

} // namespace ggxcl::detail
