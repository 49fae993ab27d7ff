// c_handles.hpp - what the C API's opaque handles hold, and the checks of
// the pointers every entry point receives.
#pragma once

#include <memory>
#include <string>

#include "c_api/c_events.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/ggxcl.h"
#include "ggxcl/sampler.hpp"
#include "ggxcl/user_sampler.hpp"

// A sampler and what the C calls read of its device, once.
struct ggxcl_sampler {
    explicit ggxcl_sampler(const std::string& selector) : sampler(selector) {}
    ggxcl_sampler(const cl::Context& context, const cl::Device& device) : sampler(context, device) {}
    ggxcl::Sampler sampler;
    const std::string device_name = sampler.device_name();
};

struct ggxcl_user_sampler {
    std::shared_ptr<const ggxcl::UserSampler> sampler;
};

namespace ggxcl::capi {

// The object `pointer` points to; InvalidArgument naming `parameter` when it is NULL.
template <class T>
T& require(T* pointer, const char* parameter)
{
    if (!pointer)
        throw InvalidArgument(parameter, "NULL", "a valid pointer");
    return *pointer;
}

// `pointer` itself (an OpenCL handle, a string); InvalidArgument naming `parameter` when it is NULL.
template <class T>
T* non_null(T* pointer, const char* parameter)
{
    if (!pointer)
        throw InvalidArgument(parameter, "NULL", "a valid pointer");
    return pointer;
}

} // namespace ggxcl::capi
