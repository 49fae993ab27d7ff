// cli_api.hpp - the API a `ggx` suite written once for both back ends runs
// on: GGX_TEST_API=opencl (the default: no flag, the default device) or
// vulkan (`--api vulkan --shader-language L`, L from GGX_TEST_SHADER_LANGUAGE,
// glsl by default).  CTest runs such a suite once more on Vulkan, under the
// validation layer (tests/CMakeLists.txt: ggx_cli_backend_test).
#pragma once

#include <cstdlib>
#include <string>

#include "cli_runner.hpp"
#include "skip.hpp"

namespace ggxtest {

struct CliApi {
    bool vulkan = false;
    std::string flags;  // what a command takes to run on this API ("" on OpenCL)
    std::string label;  // what the outputs call the API: "opencl", "vulkan (glsl)", "vulkan (hlsl)"
};

inline const CliApi& cli_api()
{
    static const CliApi api = [] {
        const char* name = std::getenv("GGX_TEST_API");
        if (!name || std::string(name) != "vulkan")
            return CliApi{false, "", "opencl"};
        const char* language = std::getenv("GGX_TEST_SHADER_LANGUAGE");
        const std::string l = language && *language ? language : "glsl";
        return CliApi{true, " --api vulkan --shader-language " + l, "vulkan (" + l + ")"};
    }();
    return api;
}

// `command ARGS` with the suite's API flags after the command's name.
inline std::string on_api(const std::string& command_and_args)
{
    const std::size_t end = command_and_args.find(' ');
    if (end == std::string::npos)
        return command_and_args + cli_api().flags;
    return command_and_args.substr(0, end) + cli_api().flags + command_and_args.substr(end);
}

// Runs `ggx` on the suite's API (stderr in the case's scratch folder); see on_api.
inline Run ggx_on_api(const std::string& command_and_args)
{
    return ggx(on_api(command_and_args));
}

// Whether the suite's API has a device here; else records a skip naming what to install.
inline bool cli_api_present()
{
    static const bool present =
        !cli_api().vulkan ||
        run_ggx("devices --api vulkan", ScratchFolder::current() / "devices.txt").status == 0;
    return skip_unless(present, "needs a Vulkan device: a ggxcl built with Vulkan (libvulkan-dev, libshaderc-dev) "
                                "and a driver (apt-get install mesa-vulkan-drivers)");
}

} // namespace ggxtest
