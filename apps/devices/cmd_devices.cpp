// cmd_devices.cpp - `ggx devices`: every OpenCL device, then every Vulkan
// device, each with the selector to pass to --device (Vulkan's with the
// vulkan: prefix), its API versions and its limits.  --api lists one API.
// With no OpenCL device the command still lists Vulkan's, then fails with
// the message that says how to install one (OpenCL is the default API).
#include <cstdint>
#include <iostream>
#include <string>

#include <ggxcl/ggxcl.hpp>

#include "cli_values.hpp"
#include "commands.hpp"

namespace ggxapp {

namespace {

std::string mebibytes(std::uint64_t bytes)
{
    return std::to_string(bytes >> 20) + " MiB";
}

void list_opencl_devices()
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

void list_vulkan_devices()
{
    for (const ggxcl::VulkanDeviceInfo& d : ggxcl::list_vulkan_devices()) {
        std::cout << "vulkan:" << d.index << ": " << d.name << " (" << d.type << ", Vulkan " << d.api_version
                  << ")  select with --device vulkan:" << d.index << " or --api vulkan --device " << d.index << "\n";
        std::cout << "   storage buffers up to " << mebibytes(d.max_storage_buffer_range) << ", work-groups up to "
                  << d.max_work_groups_x << " x " << d.max_work_groups_y << ", push constants "
                  << d.max_push_constants << " B, shared memory " << d.max_shared_memory / 1024
                  << " KiB; 64-bit integers " << (d.int64 ? "yes" : "no (the samplers cannot run)") << "\n";
    }
}

void list_devices(const std::string& api)
{
    if (api == "vulkan") {
        list_vulkan_devices();
        return;
    }
    std::string opencl_error;
    try {
        list_opencl_devices();
    } catch (const ggxcl::DeviceError& e) {
        if (api == "opencl")
            throw;
        opencl_error = e.what();
    }
    if (api == "all") {
        try {
            list_vulkan_devices();
        } catch (const ggxcl::DeviceError& e) {
            std::cout << "no Vulkan device: " << e.what() << "\n";
        }
    }
    if (!opencl_error.empty())
        throw ggxcl::DeviceError(opencl_error);
}

} // namespace

Prepare add_devices_command(CLI::App& app)
{
    CLI::App* cmd = app.add_subcommand("devices", "List OpenCL and Vulkan devices and their selectors");
    auto api = std::make_shared<std::string>("all");
    cmd->add_option("--api", *api, "all, opencl or vulkan: the devices of which API");
    return [cmd, api]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        if (*api != "all" && *api != "opencl" && *api != "vulkan")
            throw UsageError("--api", *api, "all, opencl or vulkan");
        return Work{[api] { list_devices(*api); }, {}};
    };
}

} // namespace ggxapp
