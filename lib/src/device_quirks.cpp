// device_quirks.cpp - the build options a device needs (see device_quirks.hpp).
#include "device_quirks.hpp"

namespace ggxcl::detail {

std::string device_quirk_options(const cl::Device& device)
{
    cl::Platform platform(device.getInfo<CL_DEVICE_PLATFORM>());
    if (platform.getInfo<CL_PLATFORM_NAME>().find("Oclgrind") != std::string::npos)
        return " -DGGX_NO_RESTRICT=1";
    return "";
}

} // namespace ggxcl::detail
