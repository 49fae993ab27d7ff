// error.hpp - the exceptions ggxcl throws: bad arguments (naming the
// parameter, the value and what is allowed), OpenCL failures (carrying the
// CL error name; a lost device has its own type) and program build
// failures (with options and build log).
#pragma once

#include <stdexcept>
#include <string>

namespace ggxcl {

// Base of every ggxcl exception.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A caller passed a value outside what is allowed.
class InvalidArgument : public Error {
public:
    InvalidArgument(const std::string& parameter, const std::string& value, const std::string& allowed);
    const std::string& parameter() const { return parameter_; }
    const std::string& allowed() const { return allowed_; }

private:
    std::string parameter_, allowed_;
};

// No OpenCL platform, or no device at all.
class DeviceError : public Error {
public:
    using Error::Error;
};

// Devices exist but none matches the selector; the message lists them.
class NoMatchingDevice : public DeviceError {
public:
    using DeviceError::DeviceError;
};

// An OpenCL call failed; `what()` holds the call and the CL error name.
class ClError : public Error {
public:
    ClError(const std::string& call, int code);
    int code() const { return code_; }

protected:
    ClError(int code, const std::string& message) : Error(message), code_(code) {}

private:
    int code_;
};

// The device stopped working during a call (CL_DEVICE_NOT_AVAILABLE, or
// its queue or context became invalid): the call's results are incomplete.
// The Sampler cannot be used again; make a new one once the device is back.
class DeviceLost : public ClError {
public:
    DeviceLost(const std::string& call, int code);
};

// clBuildProgram failed, or shaderc (Vulkan; code() is then CL_BUILD_PROGRAM_FAILURE): the message carries the CL error name, the build
// options and the device's build log (after `summary`, when given: for a
// user sampler, the first error with its file and line).
class BuildError : public ClError {
public:
    BuildError(int code, const std::string& device, const std::string& options, const std::string& log,
               const std::string& summary = "");
    // A shader that did not compile (Vulkan): `message` names the file and line first, then what was built.
    BuildError(const std::string& message, const std::string& log);
    const std::string& log() const { return log_; }

private:
    std::string log_;
};

// The symbolic name of an OpenCL error code, e.g. "CL_OUT_OF_RESOURCES".
std::string cl_error_name(int code);

} // namespace ggxcl
