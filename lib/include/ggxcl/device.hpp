// device.hpp - finding OpenCL devices and choosing one: by an explicit
// selector, else by the GGXCL_DEVICE environment variable, else the first
// device found.  A selector is an index into list_devices() or a
// case-insensitive substring of "platform / device".
#pragma once

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
    cl::Device device;

    // "platform / device", the string substring selectors are matched against.
    std::string label() const { return platform + " / " + name; }
};

// Every device of every platform, in platform order.  Throws DeviceError
// (saying how to install PoCL) when there is no OpenCL platform at all.
std::vector<DeviceInfo> list_devices();

// The device a selector names; throws DeviceError listing what exists when
// nothing matches.  An empty selector means GGXCL_DEVICE, else the first device.
DeviceInfo select_device(const std::string& selector = "");

} // namespace ggxcl
