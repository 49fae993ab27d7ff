// cl_call.hpp - runs OpenCL C++ binding calls and turns their cl::Error
// into ggxcl::ClError, which carries the CL error name (DeviceLost for the
// codes of a lost device).
#pragma once

#include "device_faults.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/opencl.hpp"

namespace ggxcl::detail {

template <typename Body>
auto translate_cl_errors(Body&& body) -> decltype(body())
{
    try {
        return body();
    } catch (const cl::Error& e) {
        if (is_device_lost(e.err()))
            throw DeviceLost(e.what(), e.err());
        throw ClError(e.what(), e.err());
    }
}

} // namespace ggxcl::detail
