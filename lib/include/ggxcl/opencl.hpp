// opencl.hpp - includes the Khronos OpenCL C++ bindings with the settings
// ggxcl is built with: the OpenCL 1.2 API (which PoCL and every vendor driver
// provide) and exceptions (cl::Error), so that a program including ggxcl
// gets the same inline definitions as the library.  Including the bindings
// without exceptions before a ggxcl header is refused.
#pragma once

#if defined(CL_HPP_) && !defined(CL_HPP_ENABLE_EXCEPTIONS)
#error "ggxcl uses the OpenCL C++ bindings with exceptions: include a ggxcl header before <CL/opencl.hpp>, or define CL_HPP_ENABLE_EXCEPTIONS"
#endif
#ifndef CL_HPP_ENABLE_EXCEPTIONS
#define CL_HPP_ENABLE_EXCEPTIONS
#endif

#ifndef CL_HPP_TARGET_OPENCL_VERSION
#define CL_HPP_TARGET_OPENCL_VERSION 120
#endif
#ifndef CL_HPP_MINIMUM_OPENCL_VERSION
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#endif
#include <CL/opencl.hpp>
