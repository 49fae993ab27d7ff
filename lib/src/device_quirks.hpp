// device_quirks.hpp - build options that the runtime adds for a device
// whose compiler cannot take some portable OpenCL C construct.  Users never
// set them; every program the library builds gets them.
#pragma once

#include <string>

#include "ggxcl/opencl.hpp"

namespace ggxcl::detail {

// " -DGGX_NO_RESTRICT=1" for Oclgrind: its LLVM does not know the
// llvm.experimental.noalias.scope.decl intrinsic that clang emits when a
// function with restrict pointers is inlined, and such kernels fail to be
// created (CL_INVALID_KERNEL_NAME).  Empty for every other device.
std::string device_quirk_options(const cl::Device& device);

} // namespace ggxcl::detail
