// sampler_stress.cpp - Sampler::stress: the stability map's cases through
// kernels/ggx_stress.cl, built for the request (method, guards, dielectric,
// a user sampler, the precision's options) on the sampler's queue; and open_backend's opener of
// the OpenCL back end (backend_factories.hpp).
#include <string>

#include "backend_factories.hpp"
#include "cl_call.hpp"
#include "stress_request.hpp"
#include "ggxcl/sampler.hpp"
#include "ggxcl/user_kernels.hpp"

namespace ggxcl {

namespace {

std::string stress_options(const cl::Device& device, const StressRequest& request)
{
    return detail::stress_defines(request) + device_options(device) + precision_options(device, request.precision);
}

// The program, a user sampler's build error led by its own summary.
cl::Program stress_program(const Sampler& sampler, const StressRequest& request)
{
    const std::string options = stress_options(sampler.device(), request);
    try {
        return build_user_program(sampler.context(), sampler.device(), program_source("ggx_stress.cl", options),
                                  options);
    } catch (const BuildError& error) {
        if (!request.user)
            throw;
        throw BuildError(error.code(), sampler.device_name(), options, error.log(), user_build_summary(error.log()));
    }
}

} // namespace

std::vector<float> Sampler::stress(const StressRequest& request, const std::vector<float>& in, std::uint32_t count)
{
    const detail::StressPlanes planes = detail::checked_stress(request, in, count);
    std::vector<float> out(planes.out * count);
    if (count == 0)
        return out;
    const cl::Program program = stress_program(*this, request);
    detail::translate_cl_errors([&] {
        cl::Kernel kernel(program, "ggx_stress");
        cl::Buffer in_buffer(context_, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, in.size() * sizeof(float),
                             const_cast<float*>(in.data()));
        cl::Buffer out_buffer(context_, CL_MEM_WRITE_ONLY, out.size() * sizeof(float));
        kernel.setArg(0, cl_uint(count));
        kernel.setArg(1, in_buffer);
        kernel.setArg(2, out_buffer);
        const std::size_t group = work_group_size(), global = (std::size_t(count) + group - 1) / group * group;
        queue_.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NDRange(group));
        queue_.enqueueReadBuffer(out_buffer, CL_TRUE, 0, out.size() * sizeof(float), out.data());
    });
    return out;
}

namespace detail {

std::unique_ptr<Backend> open_opencl_backend(const std::string& selector)
{
    return std::make_unique<Sampler>(selector);
}

} // namespace detail

} // namespace ggxcl
