// cl_call.hpp - runs OpenCL C++ binding calls and turns their cl::Error
// into ggxcl::ClError, which carries the CL error name.
#pragma once

#include "ggxcl/error.hpp"
#include "ggxcl/opencl.hpp"

namespace ggxcl::detail {

template <typename Body>
auto translate_cl_errors(Body&& body) -> decltype(body())
{
    try {
        return body();
    } catch (const cl::Error& e) {
        throw ClError(e.what(), e.err());
    }
}

} // namespace ggxcl::detail
