// main.cpp - the `ggx` command-line tool.  Exit status: 0 success, 1 runtime
// failure, 2 bad usage; messages go to stderr on one line.
#include <iostream>

#include <ggxcl/ggxcl.hpp>

#include "atomic_file.hpp"
#include "cli_values.hpp"
#include "commands.hpp"

int main(int argc, char** argv)
{
    ggxapp::remember_command_line(argc, argv);
    ggxapp::install_interrupt_cleanup();
    CLI::App app{"ggx - GGX microfacet importance samplers on OpenCL devices (ggxcl " +
                 std::string(ggxcl::version()) + ")"};
    app.require_subcommand(1);
    std::vector<ggxapp::Action> actions = {ggxapp::add_devices_command(app), ggxapp::add_sample_command(app),
                                           ggxapp::add_histogram_command(app), ggxapp::add_demo_command(app),
                                           ggxapp::add_merge_command(app), ggxapp::add_bench_command(app),
                                           ggxapp::add_stress_command(app)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "ggx: " << e.what() << " (see ggx --help)\n";
        return 2;
    }
    try {
        for (const ggxapp::Action& action : actions)
            action();
    } catch (const ggxapp::CheckFailed& e) {
        std::cerr << "ggx: check failed: " << e.what() << "\n";
        return 1;
    } catch (const ggxapp::UsageError& e) {
        std::cerr << "ggx: " << e.what() << "\n";
        return 2;
    } catch (const ggxcl::NoMatchingDevice& e) {
        std::cerr << "ggx: --device: " << e.what() << "\n";
        return 2;
    } catch (const ggxcl::InvalidArgument& e) {
        std::cerr << "ggx: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "ggx: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
