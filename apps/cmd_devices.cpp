// cmd_devices.cpp - `ggx devices`: every OpenCL platform and device with
// the selector to pass to --device or GGXCL_DEVICE.
#include <iostream>

#include <ggxcl/ggxcl.hpp>

#include "commands.hpp"

namespace ggxapp {

namespace {

void list_devices()
{
    for (const ggxcl::DeviceInfo& d : ggxcl::list_devices())
        std::cout << d.index << ": " << d.label() << " (" << d.type << ", " << d.compute_units
                  << " compute units)  select with --device " << d.index << " or GGXCL_DEVICE=" << d.index << "\n";
}

} // namespace

Prepare add_devices_command(CLI::App& app)
{
    CLI::App* cmd = app.add_subcommand("devices", "List OpenCL devices and their selectors");
    return [cmd]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        return Work{list_devices, {}};
    };
}

} // namespace ggxapp
