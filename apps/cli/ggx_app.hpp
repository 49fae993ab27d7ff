// ggx_app.hpp - the whole `ggx` command line: the CLI11 app with every
// subcommand registered, as main() and fuzz/fuzz_cli use it.  Parse with
// `cli`, then prepare() checks the options of the subcommand given.
#pragma once

#include <vector>

#include <CLI/CLI.hpp>

#include "commands.hpp"

namespace ggxapp {

class GgxApp {
public:
    GgxApp();
    CLI::App cli;

    // The work of the subcommand given (one after a successful parse);
    // throws UsageError or ggxcl::InvalidArgument on bad usage.
    std::vector<Work> prepare() const;

private:
    std::vector<Prepare> commands_;
};

} // namespace ggxapp
