// device.cpp - device listing and selection (index or name substring,
// explicit or from GGXCL_DEVICE).
#include "ggxcl/device.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "ggxcl/error.hpp"

namespace ggxcl {

namespace {

std::string device_type_name(cl_device_type type)
{
    if (type & CL_DEVICE_TYPE_GPU) return "GPU";
    if (type & CL_DEVICE_TYPE_CPU) return "CPU";
    if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
    return "other";
}

std::string lowercase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

bool is_index(const std::string& text)
{
    return !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::vector<cl::Platform> platforms_or_throw()
{
    std::vector<cl::Platform> platforms;
    cl_int status = CL_SUCCESS;
    try {
        status = cl::Platform::get(&platforms);
    } catch (const cl::Error& e) {
        status = e.err();
    }
    if (status != CL_SUCCESS || platforms.empty())
        throw DeviceError("no OpenCL platform found (" + cl_error_name(status) +
                          "); install one, e.g. on Debian: apt-get install pocl-opencl-icd ocl-icd-libopencl1");
    return platforms;
}

std::string describe_all(const std::vector<DeviceInfo>& devices)
{
    std::string text;
    for (const DeviceInfo& d : devices)
        text += (text.empty() ? " " : "; ") + std::to_string(d.index) + ": " + d.label() + " (" + d.type + ")";
    return text;
}

} // namespace

std::vector<DeviceInfo> list_devices()
{
    std::vector<DeviceInfo> devices;
    for (const cl::Platform& platform : platforms_or_throw()) {
        std::vector<cl::Device> found;
        try {
            platform.getDevices(CL_DEVICE_TYPE_ALL, &found);
        } catch (const cl::Error&) {
            continue;  // a platform without devices reports CL_DEVICE_NOT_FOUND
        }
        for (const cl::Device& device : found) {
            DeviceInfo info;
            info.index = devices.size();
            info.platform = platform.getInfo<CL_PLATFORM_NAME>();
            info.name = device.getInfo<CL_DEVICE_NAME>();
            info.type = device_type_name(device.getInfo<CL_DEVICE_TYPE>());
            info.compute_units = device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
            info.device = device;
            devices.push_back(info);
        }
    }
    if (devices.empty())
        throw DeviceError("OpenCL platforms exist but none has a device");
    return devices;
}

DeviceInfo select_device(const std::string& selector)
{
    std::string wanted = selector;
    std::string source = "selector";
    if (wanted.empty()) {
        const char* env = std::getenv("GGXCL_DEVICE");
        wanted = env ? env : "";
        source = "GGXCL_DEVICE";
    }
    std::vector<DeviceInfo> devices = list_devices();
    if (wanted.empty())
        return devices.front();
    if (is_index(wanted)) {
        std::size_t index = std::stoul(wanted);
        if (index < devices.size())
            return devices[index];
    } else {
        for (const DeviceInfo& d : devices)
            if (lowercase(d.label()).find(lowercase(wanted)) != std::string::npos)
                return d;
    }
    throw NoMatchingDevice("no OpenCL device matches " + source + " '" + wanted +
                      "'; give an index or part of a name from:" + describe_all(devices));
}

} // namespace ggxcl
