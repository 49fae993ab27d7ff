// main.cpp - the `ggx` command-line tool.  Exit status: 0 success, 1 runtime
// failure, 2 bad usage; messages go to stderr on one line.  Every option is
// checked (GgxApp::prepare) before any device is opened or file written.
#include <iostream>

#include <ggxcl/ggxcl.hpp>

#include "atomic_file.hpp"
#include "cli_errors.hpp"
#include "cli_values.hpp"
#include "ggx_app.hpp"

int main(int argc, char** argv)
{
    ggxapp::remember_command_line(argc, argv);
    ggxapp::install_interrupt_cleanup();
    ggxapp::GgxApp app;
    if (const std::optional<std::string> unknown = ggxapp::unknown_command(app.cli, argc, argv)) {
        std::cerr << "ggx: " << *unknown << "\n";
        return 2;
    }
    try {
        app.cli.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.cli.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.cli.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "ggx: " << ggxapp::parse_error_message(e, app.cli) << "\n";
        return 2;
    }
    try {
        for (const ggxapp::Work& work : app.prepare())
            work.run();
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
