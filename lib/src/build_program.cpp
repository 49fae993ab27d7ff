// build_program.cpp - building a program from source with the library's
// errors (the build log travels in BuildError).
#include "build_program.hpp"

#include "ggxcl/error.hpp"

namespace ggxcl::detail {

namespace {

std::string build_log(const cl::Program& program, const cl::Device& device)
{
    try {
        return program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
    } catch (const cl::Error&) {
        return "(no build log available)";
    }
}

} // namespace

cl::Program build_program(const cl::Context& context, const cl::Device& device, const std::string& source,
                          const std::string& options)
{
    cl::Program program;
    try {
        program = cl::Program(context, source);
    } catch (const cl::Error& e) {
        throw ClError("clCreateProgramWithSource", e.err());
    }
    try {
        program.build({device}, options.c_str());
    } catch (const cl::Error& e) {
        throw BuildError(e.err(), device.getInfo<CL_DEVICE_NAME>(), options, build_log(program, device));
    }
    return program;
}

} // namespace ggxcl::detail
