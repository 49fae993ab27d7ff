// device.hpp - finding OpenCL devices and choosing one: by an explicit
// selector, else by the GGXCL_DEVICE environment variable, else the first
// device found.  A selector is an index into list_devices() or a
// case-insensitive substring of "platform / device" or of the platform's
// vendor ("pocl", "rusticl", "nvidia").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ggxcl/opencl.hpp"

namespace ggxcl {

struct DeviceInfo {
    std::size_t index = 0;  // position in list_devices(): a valid selector
    std::string platform;   // platform name, e.g. "Portable Computing Language"
    std::string name;       // device name
    std::string type;       // "CPU", "GPU", "accelerator" or "other"
    unsigned compute_units = 0;
    std::string vendor;          // platform vendor, e.g. "The pocl project" (selectors match it too)
    std::string opencl_version;  // CL_DEVICE_VERSION, e.g. "OpenCL 1.2 pocl 3.1"
    std::string opencl_c_version;  // CL_DEVICE_OPENCL_C_VERSION
    std::string driver_version;
    std::size_t max_work_group_size = 0;
    std::uint64_t max_alloc_bytes = 0, global_mem_bytes = 0, local_mem_bytes = 0;
    bool fp64 = false;           // double precision on the device (the kernels use none)
    cl::Device device;

    // "platform / device", the string substring selectors are matched against.
    std::string label() const { return platform + " / " + name; }
};

// Every device of every platform, in platform order; a platform without a
// device (Mesa's rusticl without RUSTICL_ENABLE, Clover without an AMD GPU)
// is skipped.  Throws DeviceError when there is no OpenCL platform, or no
// platform has a device, saying how to install PoCL or enable rusticl.
std::vector<DeviceInfo> list_devices();

// The device a selector names; throws DeviceError listing what exists when
// nothing matches.  An empty selector means GGXCL_DEVICE, else the first device.
DeviceInfo select_device(const std::string& selector = "");

} // namespace ggxcl
