// c_status.cpp - exceptions to status codes, and the per-thread last error
// the C API's error queries read.
#include "c_api/c_status.hpp"

#include <new>

#include "ggxcl/error.hpp"
#include "ggxcl/opencl.hpp"

namespace ggxcl::capi {
namespace {

struct LastError {
    std::string message, parameter, build_log;
    cl_int cl_code = CL_SUCCESS;
};

LastError& last_error()
{
    thread_local LastError error;
    return error;
}

ggxcl_status record(ggxcl_status status, std::string message, std::string parameter = "", cl_int code = CL_SUCCESS,
                    std::string log = "")
{
    LastError& error = last_error();
    error.message = std::move(message);
    error.parameter = std::move(parameter);
    error.cl_code = code;
    error.build_log = std::move(log);
    return status;
}

} // namespace

ggxcl_status record_current_exception() noexcept
{
    try {
        try {
            throw;
        } catch (const InvalidArgument& e) {
            return record(GGXCL_INVALID_ARGUMENT, e.what(), e.parameter());
        } catch (const NoMatchingDevice& e) {
            return record(GGXCL_NO_MATCHING_DEVICE, e.what());
        } catch (const DeviceError& e) {
            return record(GGXCL_DEVICE_ERROR, e.what());
        } catch (const BuildError& e) {
            return record(GGXCL_BUILD_ERROR, e.what(), "", e.code(), e.log());
        } catch (const DeviceLost& e) {
            return record(GGXCL_DEVICE_LOST, e.what(), "", e.code());
        } catch (const ClError& e) {
            return record(GGXCL_CL_ERROR, e.what(), "", e.code());
        } catch (const cl::Error& e) {
            return record(GGXCL_CL_ERROR, std::string(e.what()) + ": " + cl_error_name(e.err()), "", e.err());
        } catch (const std::bad_alloc&) {
            return record(GGXCL_OUT_OF_HOST_MEMORY, "out of host memory");
        } catch (const std::exception& e) {
            return record(GGXCL_ERROR, e.what());
        } catch (...) {
            return record(GGXCL_ERROR, "an unknown exception");
        }
    } catch (...) {  // recording itself ran out of memory
        return GGXCL_OUT_OF_HOST_MEMORY;
    }
}

} // namespace ggxcl::capi

using ggxcl::capi::last_error;

extern "C" {

const char* ggxcl_status_string(ggxcl_status status)
{
    switch (status) {
    case GGXCL_SUCCESS: return "GGXCL_SUCCESS";
    case GGXCL_INVALID_ARGUMENT: return "GGXCL_INVALID_ARGUMENT";
    case GGXCL_DEVICE_ERROR: return "GGXCL_DEVICE_ERROR";
    case GGXCL_NO_MATCHING_DEVICE: return "GGXCL_NO_MATCHING_DEVICE";
    case GGXCL_CL_ERROR: return "GGXCL_CL_ERROR";
    case GGXCL_DEVICE_LOST: return "GGXCL_DEVICE_LOST";
    case GGXCL_BUILD_ERROR: return "GGXCL_BUILD_ERROR";
    case GGXCL_OUT_OF_HOST_MEMORY: return "GGXCL_OUT_OF_HOST_MEMORY";
    case GGXCL_ERROR: return "GGXCL_ERROR";
    }
    return "an unknown ggxcl_status";
}

const char* ggxcl_last_error(void) { return last_error().message.c_str(); }
const char* ggxcl_last_error_parameter(void) { return last_error().parameter.c_str(); }
cl_int ggxcl_last_cl_error(void) { return last_error().cl_code; }
const char* ggxcl_last_build_log(void) { return last_error().build_log.c_str(); }

} // extern "C"
