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

std::string trimmed(std::string text)
{
    while (!text.empty() && (std::isspace(static_cast<unsigned char>(text.back())) || text.back() == '\0'))
        text.pop_back();
    std::size_t start = 0;
    while (start < text.size() && std::isspace(static_cast<unsigned char>(text[start])))
        ++start;
    return text.substr(start);
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

DeviceInfo describe_device(const cl::Platform& platform, const cl::Device& device, std::size_t index)
{
    DeviceInfo info;
    info.index = index;
    info.platform = platform.getInfo<CL_PLATFORM_NAME>();
    info.vendor = platform.getInfo<CL_PLATFORM_VENDOR>();
    info.name = trimmed(device.getInfo<CL_DEVICE_NAME>());
    info.type = device_type_name(device.getInfo<CL_DEVICE_TYPE>());
    info.compute_units = device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
    info.opencl_version = trimmed(device.getInfo<CL_DEVICE_VERSION>());
    info.opencl_c_version = trimmed(device.getInfo<CL_DEVICE_OPENCL_C_VERSION>());
    info.driver_version = trimmed(device.getInfo<CL_DRIVER_VERSION>());
    info.max_work_group_size = device.getInfo<CL_DEVICE_MAX_WORK_GROUP_SIZE>();
    info.max_alloc_bytes = device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
    info.global_mem_bytes = device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
    info.local_mem_bytes = device.getInfo<CL_DEVICE_LOCAL_MEM_SIZE>();
    cl_device_fp_config fp64 = 0;
    info.fp64 = device.getInfo(CL_DEVICE_DOUBLE_FP_CONFIG, &fp64) == CL_SUCCESS && fp64 != 0;
    info.device = device;
    return info;
}

// The devices of one platform; none when it has none or cannot list them.
std::vector<cl::Device> devices_of(const cl::Platform& platform)
{
    std::vector<cl::Device> found;
    try {
        platform.getDevices(CL_DEVICE_TYPE_ALL, &found);
    } catch (const cl::Error&) {
        found.clear();  // a platform without devices reports CL_DEVICE_NOT_FOUND
    }
    return found;
}

} // namespace

std::vector<DeviceInfo> list_devices()
{
    std::vector<DeviceInfo> devices;
    std::string empty_platforms;
    for (const cl::Platform& platform : platforms_or_throw()) {
        std::vector<cl::Device> found = devices_of(platform);
        if (found.empty())
            empty_platforms += (empty_platforms.empty() ? "" : ", ") + platform.getInfo<CL_PLATFORM_NAME>();
        for (const cl::Device& device : found) {
            try {
                devices.push_back(describe_device(platform, device, devices.size()));
            } catch (const cl::Error&) {
                // a device that cannot describe itself cannot run kernels either
            }
        }
    }
    if (devices.empty())
        throw DeviceError("no OpenCL platform has a device (platforms without one: " + empty_platforms +
                          "); install PoCL for the CPU (apt-get install pocl-opencl-icd), or enable Mesa's "
                          "rusticl on the CPU with RUSTICL_ENABLE=llvmpipe (apt-get install mesa-opencl-icd)");
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
            if (lowercase(d.label() + " / " + d.vendor).find(lowercase(wanted)) != std::string::npos)
                return d;
    }
    throw NoMatchingDevice("no OpenCL device matches " + source + " '" + wanted +
                      "'; give an index or part of a name from:" + describe_all(devices));
}

} // namespace ggxcl
