// ggx_app.cpp - the `ggx` app: its description and subcommands, in the
// order `ggx --help` lists them.
#include "ggx_app.hpp"

#include <ggxcl/ggxcl.hpp>

#include "option_help.hpp"

namespace ggxapp {

GgxApp::GgxApp()
    : cli{"ggx - GGX microfacet importance samplers on OpenCL devices (ggxcl " + std::string(ggxcl::version()) + ")"}
{
    cli.require_subcommand(1);
    commands_ = {add_devices_command(cli), add_methods_command(cli), add_sample_command(cli), add_histogram_command(cli),
                 add_demo_command(cli),    add_merge_command(cli),  add_bench_command(cli),
                 add_converge_command(cli), add_stress_command(cli)};
    describe_option_values(cli);
}

std::vector<Work> GgxApp::prepare() const
{
    std::vector<Work> works;
    for (const Prepare& prepare : commands_)
        if (std::optional<Work> work = prepare())
            works.push_back(std::move(*work));
    return works;
}

} // namespace ggxapp
