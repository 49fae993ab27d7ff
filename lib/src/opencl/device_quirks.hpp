// device_quirks.hpp - what the runtime knows of particular OpenCL
// implementations: build options for a compiler that cannot take some
// portable OpenCL C construct (users never set them; every program the
// library builds gets them), the options of a precision mode on a device
// (what its single-precision config allows), and which platforms cache
// programs themselves.
#pragma once

#include <string>

#include "ggxcl/opencl.hpp"
#include "ggxcl/params.hpp"

namespace ggxcl::detail {

// " -DGGX_NO_RESTRICT=1" for Oclgrind: its LLVM does not know the
// llvm.experimental.noalias.scope.decl intrinsic that clang emits when a
// function with restrict pointers is inlined, and such kernels fail to be
// created (CL_INVALID_KERNEL_NAME); " -DGGX_NO_BITREVERSE=1" there too: the
// same holds for llvm.bitreverse, which clang makes of the Sobol points' bit
// reversal (kernels/ggx_sobol.h).  " -DGGX_NO_FMA=1" for a device whose
// single-precision config lacks CL_FP_FMA: there fma() is a slow software
// routine and kernels/ggx_sincos.h uses a * b + c.  Empty for most devices.
std::string device_quirk_options(const cl::Device& device);

// The build options of precision mode `precision` on a device whose
// CL_DEVICE_SINGLE_FP_CONFIG is `single_fp_config`: relaxed,
// " -cl-fast-relaxed-math"; precise, " -cl-fp32-correctly-rounded-divide-sqrt"
// where the config has CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT (OpenCL allows
// the option only there), else none (division within 2.5 ulp, sqrt within
// 3 ulp).  ggxcl::precision_options (user_kernels.hpp) reads the config.
std::string precision_options_for(Precision precision, cl_device_fp_config single_fp_config);

// Whether the platform keeps compiled programs between processes itself
// (PoCL in ~/.cache/pocl, NVIDIA in ~/.nv/ComputeCache): there the
// library's own binary cache is off unless GGXCL_PROGRAM_CACHE names a
// directory.  Asking PoCL for a binary also compiles every kernel of the
// program, which a build from its cache does not.
bool platform_caches_programs(const cl::Device& device);

// Whether the device is Oclgrind, whose uninitialized-value checker reports
// the histogram's count kernel reading, as local-memory addresses, the bin
// indices the bins kernel wrote into a buffer created without host data
// (every index is written first; a minimal two-kernel chain is not
// reported, so the cause inside Oclgrind is not pinned down).  A host write
// of zeros first makes the reports go away: the library does that there.
bool kernel_writes_look_uninitialized(const cl::Device& device);

} // namespace ggxcl::detail
