// device_quirks.cpp - the build options a device needs, and those of a
// precision mode on it (see device_quirks.hpp).
#include "device_quirks.hpp"

namespace ggxcl::detail {

namespace {

std::string platform_name(const cl::Device& device)
{
    return cl::Platform(device.getInfo<CL_DEVICE_PLATFORM>()).getInfo<CL_PLATFORM_NAME>();
}

} // namespace

std::string device_quirk_options(const cl::Device& device)
{
    std::string options;
    if (platform_name(device).find("Oclgrind") != std::string::npos)
        options += " -DGGX_NO_RESTRICT=1 -DGGX_NO_BITREVERSE=1";
    if (!(device.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>() & CL_FP_FMA))
        options += " -DGGX_NO_FMA=1";
    return options;
}

std::string precision_options_for(Precision precision, cl_device_fp_config single_fp_config)
{
    if (precision == Precision::relaxed)
        return " -cl-fast-relaxed-math";
    if (single_fp_config & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT)
        return " -cl-fp32-correctly-rounded-divide-sqrt";
    return "";
}

bool kernel_writes_look_uninitialized(const cl::Device& device)
{
    return platform_name(device).find("Oclgrind") != std::string::npos;
}

bool platform_caches_programs(const cl::Device& device)
{
    const std::string name = platform_name(device);
    return name == "Portable Computing Language" || name.find("NVIDIA") != std::string::npos;
}

} // namespace ggxcl::detail
