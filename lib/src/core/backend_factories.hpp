// backend_factories.hpp - how open_backend (backend.cpp) and
// benchmark::device_jobs (device_jobs.cpp) reach each back end without
// including it: each back end defines its own opener (opencl/, vulkan/; a
// build without Vulkan: vulkan_absent.cpp).
#pragma once

#include <memory>
#include <string>

#include "ggxcl/backend.hpp"
#include "ggxcl/benchmark.hpp"

namespace ggxcl::detail {

std::unique_ptr<Backend> open_opencl_backend(const std::string& selector);
std::unique_ptr<Backend> open_vulkan_backend(const std::string& selector, ShaderLanguage language);

// The bench's jobs on an OpenCL back end (a Sampler), in its own buffers, event-profiled.
std::unique_ptr<benchmark::DeviceJobs> opencl_device_jobs(Backend& sampler, std::uint64_t count,
                                                          benchmark::JobInputs inputs);

// The world job's request: world space, isotropic at alpha_x.
inline SampleParams world_job_params(SampleParams params)
{
    params.world_space = true;
    params.alpha_y = params.alpha_x;
    return params;
}

} // namespace ggxcl::detail
