// header_without_opencl.cpp - compiled with -DGGX_HEADER=<a public header>:
// fails to compile if that header pulls in an OpenCL header.  The headers
// of every back end (backend.hpp, results.hpp) and Vulkan's (vulkan.hpp)
// must pass; sampler.hpp, OpenCL's own, must not (the control).
#include GGX_HEADER

#if defined(CL_HPP_) || defined(__OPENCL_CL_H) || defined(__OPENCL_CL_PLATFORM_H)
#error "this header includes an OpenCL header"
#endif

int main() { return 0; }
