// cli_errors.hpp - CLI11's parse errors in the tool's own words: an unknown
// command named with the nearest one ("unknown command 'sampel'; did you
// mean 'sample'?"), an option given twice, a value missing, an unknown
// option with the nearest of its command's options.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace ggxapp {

// The message for a first argument that is no command of `app` (nothing when
// it is one, or an option such as --help).
std::optional<std::string> unknown_command(const CLI::App& app, int argc, char** argv);

// `error`, raised while parsing `app`, in the tool's words.
std::string parse_error_message(const CLI::ParseError& error, const CLI::App& app);

} // namespace ggxapp
