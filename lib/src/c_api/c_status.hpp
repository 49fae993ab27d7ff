// c_status.hpp - the C API's side of errors: every exception the library
// throws becomes a ggxcl_status, with its message, parameter, CL code and
// build log kept for the calling thread (ggxcl_last_error & co.); nothing
// thrown ever leaves a C entry point.
#pragma once


#include "ggxcl/ggxcl.h"

namespace ggxcl::capi {

// Records the exception being handled (call inside a catch block) and returns its status.
ggxcl_status record_current_exception() noexcept;

// Runs `body` (returning void), turning anything it throws into a status.
template <class Body>
ggxcl_status guarded(Body&& body) noexcept
{
    try {
        body();
        return GGXCL_SUCCESS;
    } catch (...) {
        return record_current_exception();
    }
}

} // namespace ggxcl::capi
