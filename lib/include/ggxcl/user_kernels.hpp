// user_kernels.hpp - the GGX device functions inside your own OpenCL
// kernels.  The OpenCL C headers come one per topic (ggx_math.h: D, Lambda,
// G1, G2 and the pdfs; ggx_philox.h: the uniforms of sample k;
// ggx_sample_<method>.h: one sampler each; ggx_samplers.h: all of them and
// ggx_sample_method; ggx_world.h: world space), and every name they define
// starts with ggx_ (macros GGX_).  Two ways to use them, same functions,
// same bits:
//   include: `#include "ggx_samplers.h"` in your source, built with
//            device_include_option() in the options (build_user_program
//            adds it);
//   prepend: kernel_source("ggx_samplers.h") + your source (kernel_sources.hpp),
//            built with device_options(device) among the options.
// Either way, precision_options(device, precision) among the options gives
// the arithmetic of that precision mode, as Sampler::enqueue has it.
#pragma once

#include <string>

#include "ggxcl/opencl.hpp"
#include "ggxcl/params.hpp"

namespace ggxcl {

// A directory holding this library's device headers, for `-I`:
//   1. $GGXCL_DEVICE_INCLUDE_DIR when set (it must hold ggx_samplers.h);
//   2. else a copy of the embedded headers (self-contained: includes
//      expanded), written once per library version under
//      $XDG_CACHE_HOME/ggxcl (or ~/.cache/ggxcl, else the temporary
//      directory) and reused while its text still matches, so the headers
//      always match the library, wherever (and whether) it is installed.
// Throws Error when no such directory exists and none can be written.
std::string device_include_dir();

// "-I<dir>" of device_include_dir(), for the build options of a program.
std::string device_include_option();

// Writes the device headers embedded in this library (includes expanded)
// into `directory`, creating it: for offline compilers, or a place of your
// choosing to name in GGXCL_DEVICE_INCLUDE_DIR.  Throws Error on failure.
void write_device_headers(const std::string& directory);

// The options the library builds every program with on `device` (for
// instance -DGGX_NO_FMA=1 where the device has no hardware fma); a program
// of yours built without them may round differently from Sampler::enqueue.
std::string device_options(const cl::Device& device);

// The options the library builds precision mode `precision` with on
// `device` (ggxcl/params.hpp, Precision): relaxed, -cl-fast-relaxed-math;
// precise, -cl-fp32-correctly-rounded-divide-sqrt where the device reports
// CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT in CL_DEVICE_SINGLE_FP_CONFIG (PoCL
// 3.1 on the CPU does; Mesa 22.3 rusticl on llvmpipe and Oclgrind 21.10 do
// not), else none.  It starts with a space, like device_options.
std::string precision_options(const cl::Device& device, Precision precision);

// Builds `source` for `device` with the device headers on the include path,
// device_options(device) and `options` appended.  A failed build throws BuildError carrying the
// CL error name, the options and the build log.
cl::Program build_user_program(const cl::Context& context, const cl::Device& device, const std::string& source,
                               const std::string& options = "");

} // namespace ggxcl
