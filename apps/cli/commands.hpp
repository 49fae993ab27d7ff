// commands.hpp - the subcommands of the `ggx` tool.  Each registers its
// options on a CLI11 subcommand and returns its prepare step, called after
// parsing: it checks every option (writing no file and opening no device;
// only `ggx sample --uniforms` reads its file here) and returns the work to
// run, or nothing when its subcommand was not given.
// Bad usage is thus reported before any device is opened or file written.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <ggxcl/ggxcl.hpp>

namespace ggxapp {

// One batch of samples a prepared command will draw: checked parameters
// (normalized) and range.
struct Batch {
    ggxcl::SampleParams params;
    ggxcl::SampleRange range;
};

// A prepared command: `run` opens the devices and files and does the job
// (file-system checks such as a writable --out folder come first in it);
// `batches` lists what it will sample, for tests and fuzz/fuzz_cli.
struct Work {
    std::function<void()> run;
    std::vector<Batch> batches;
};

using Prepare = std::function<std::optional<Work>()>;

Prepare add_devices_command(CLI::App& app);
Prepare add_methods_command(CLI::App& app);
Prepare add_sample_command(CLI::App& app);
Prepare add_demo_command(CLI::App& app);
Prepare add_merge_command(CLI::App& app);
Prepare add_histogram_command(CLI::App& app);
Prepare add_bench_command(CLI::App& app);
Prepare add_stress_command(CLI::App& app);
Prepare add_converge_command(CLI::App& app);

// The command line as typed (program name shortened to `ggx`), for reports.
void remember_command_line(int argc, char** argv);
const std::string& command_line();

} // namespace ggxapp
