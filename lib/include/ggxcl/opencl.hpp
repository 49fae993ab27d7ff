// opencl.hpp - includes the Khronos OpenCL C++ bindings with the version
// settings ggxcl is built with (OpenCL 1.2 API, which PoCL and every vendor
// driver provide).
#pragma once

#ifndef CL_HPP_TARGET_OPENCL_VERSION
#define CL_HPP_TARGET_OPENCL_VERSION 120
#endif
#ifndef CL_HPP_MINIMUM_OPENCL_VERSION
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#endif
#include <CL/opencl.hpp>
