// option_help.hpp - what --help shows of each option's value: its kind
// (COUNT, DEGREES, PATH, LIST, ...) instead of CLI11's TEXT for every string
// option, and its default where it has one.
#pragma once

#include <CLI/CLI.hpp>

namespace ggxapp {

// Sets the value name and the shown default of every option of `app` and of
// its commands, from the values the options hold now (their defaults).
void describe_option_values(CLI::App& app);

} // namespace ggxapp
