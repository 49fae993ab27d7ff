// error.cpp - messages of the ggxcl exceptions.
#include "ggxcl/error.hpp"

namespace ggxcl {

InvalidArgument::InvalidArgument(const std::string& parameter, const std::string& value,
                                 const std::string& allowed)
    : Error("invalid " + parameter + " '" + value + "': allowed is " + allowed), parameter_(parameter), allowed_(allowed)
{
}

namespace {
std::string describe_failure(const std::string& call, int code)
{
    return call + " failed: " + cl_error_name(code) + " (" + std::to_string(code) + ")";
}
} // namespace

ClError::ClError(const std::string& call, int code) : Error(describe_failure(call, code)), code_(code) {}

DeviceLost::DeviceLost(const std::string& call, int code)
    : ClError(code, "the OpenCL device was lost or stopped responding: " + describe_failure(call, code) +
                        "; the results of this call are incomplete (nothing is written); "
                        "create a new Sampler once the device is back")
{
}

BuildError::BuildError(int code, const std::string& device, const std::string& options,
                       const std::string& log, const std::string& summary)
    : ClError(code, (summary.empty() ? "" : summary + "\n") +
                        describe_failure("clBuildProgram on '" + device + "' with options '" + options + "'",
                                         code) + "\nbuild log:\n" + log),
      log_(log)
{
}

BuildError::BuildError(const std::string& message, const std::string& log)
    : ClError(-11 /* CL_BUILD_PROGRAM_FAILURE */, message + "\nshaderc log:\n" + log), log_(log)
{
}

} // namespace ggxcl
