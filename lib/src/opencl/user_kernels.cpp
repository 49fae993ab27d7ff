// user_kernels.cpp - building a user's program with the device headers on
// its include path, the -I option that puts them there, and the options of
// the device and of a precision mode.
#include "ggxcl/user_kernels.hpp"

#include "build_program.hpp"
#include "device_quirks.hpp"

namespace ggxcl {

std::string device_include_option()
{
    const std::string dir = device_include_dir();
    // Drivers split build options at spaces; quoting is the common reading.
    if (dir.find_first_of(" \t") != std::string::npos)
        return "-I\"" + dir + "\"";
    return "-I" + dir;
}

std::string device_options(const cl::Device& device)
{
    return detail::device_quirk_options(device);
}

std::string precision_options(const cl::Device& device, Precision precision)
{
    return detail::precision_options_for(precision, device.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>());
}

cl::Program build_user_program(const cl::Context& context, const cl::Device& device, const std::string& source,
                               const std::string& options)
{
    return detail::build_program(context, device, source,
                                 device_include_option() + (options.empty() ? "" : " " + options));
}

} // namespace ggxcl
