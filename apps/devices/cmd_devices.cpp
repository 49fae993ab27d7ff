// cmd_devices.cpp - `ggx devices`: every OpenCL device with the selector to
// pass to --device or GGXCL_DEVICE, its OpenCL version and its limits.
#include <cstdint>
#include <iostream>
#include <string>

#include <ggxcl/ggxcl.hpp>

#include "commands.hpp"

namespace ggxapp {

namespace {

std::string mebibytes(std::uint64_t bytes)
{
    return std::to_string(bytes >> 20) + " MiB";
}

void list_devices()
{
    for (const ggxcl::DeviceInfo& d : ggxcl::list_devices()) {
        std::cout << d.index << ": " << d.label() << " (" << d.type << ", " << d.compute_units
                  << " compute units)  select with --device " << d.index << " or GGXCL_DEVICE=" << d.index << "\n";
        std::cout << "   " << d.opencl_version << ", " << d.opencl_c_version << ", driver " << d.driver_version
                  << "; work-groups up to " << d.max_work_group_size << "; memory " << mebibytes(d.global_mem_bytes)
                  << ", allocations up to " << mebibytes(d.max_alloc_bytes) << ", local " << d.local_mem_bytes / 1024
                  << " KiB; fp64 " << (d.fp64 ? "yes" : "no") << "\n";
    }
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
