// commands.hpp - the subcommands of the `ggx` tool; each registers its
// options on a CLI11 subcommand and returns the action to run after parsing.
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace ggxapp {

using Action = std::function<void()>;

Action add_devices_command(CLI::App& app);
Action add_sample_command(CLI::App& app);
Action add_demo_command(CLI::App& app);
Action add_merge_command(CLI::App& app);
Action add_histogram_command(CLI::App& app);
Action add_bench_command(CLI::App& app);
Action add_stress_command(CLI::App& app);

// The command line as typed (program name shortened to `ggx`), for reports.
void remember_command_line(int argc, char** argv);
const std::string& command_line();

} // namespace ggxapp
