// c_handles.hpp - what the C API's opaque handles hold, and the checks of
// the pointers every entry point receives.
#pragma once

#include <memory>
#include <string>

#include "c_api/c_events.hpp"
#include "ggxcl/backend.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/ggxcl.h"
#include "ggxcl/sampler.hpp"
#include "ggxcl/user_sampler.hpp"

// A back end, its OpenCL Sampler where it is one (null on Vulkan), and its device's name, read once.
struct ggxcl_sampler {
    explicit ggxcl_sampler(std::unique_ptr<ggxcl::Backend> owned)
        : backend(std::move(owned)), opencl(dynamic_cast<ggxcl::Sampler*>(backend.get()))
    {
    }
    const std::unique_ptr<ggxcl::Backend> backend;
    ggxcl::Sampler* const opencl;
    const std::string device_name = backend->device_name();
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

// The OpenCL Sampler of `sampler` for `call`; InvalidArgument ("sampler") naming the call on another API.
inline ggxcl::Sampler& opencl_of(const ggxcl_sampler* sampler, const char* call)
{
    const ggxcl_sampler& s = require(sampler, "sampler");
    if (!s.opencl)
        throw InvalidArgument("sampler", std::string("a ") + api_name(s.backend->api()) + " sampler",
                              std::string("an OpenCL sampler for ") + call + ", which works on OpenCL objects");
    return *s.opencl;
}

} // namespace ggxcl::capi
