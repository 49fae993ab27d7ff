// library_errors.hpp - the library's rules, reported in the CLI's terms: the
// CLI parses its options' text into a request and lets the library check it
// (ggxcl::normalized, ggxcl::view_from_angles); a refusal, an
// InvalidArgument naming a library parameter, becomes a UsageError that names
// the option instead and quotes its text as the user wrote it, with the
// library's words for what is allowed.
#pragma once

#include <map>
#include <string>
#include <utility>

#include <ggxcl/error.hpp>
#include <ggxcl/method.hpp>
#include <ggxcl/params.hpp>

#include "cli_values.hpp"

namespace ggxapp {

// The option that set a library parameter, and its text.
struct OptionText {
    std::string flag;
    std::string text;
};
// Library parameter ("alpha_x", "eta", "theta", ...) -> the option that set it.
using OptionsOfParameters = std::map<std::string, OptionText>;

// `error` as a UsageError naming the option of its parameter, or `error` itself
// when no option of `options` set that parameter.
[[noreturn]] void rethrow_in_option_terms(const ggxcl::InvalidArgument& error, const OptionsOfParameters& options);

// build() with the library's refusals in option terms.
template <class Build>
auto in_option_terms(const OptionsOfParameters& options, Build&& build) -> decltype(build())
{
    try {
        return std::forward<Build>(build)();
    } catch (const ggxcl::InvalidArgument& error) {
        rethrow_in_option_terms(error, options);
    }
}

// parse(text), a library parser of names, with its refusal as a UsageError naming `flag`, the
// text and what `allowed` says.
template <class Parse>
auto parsed_option(const std::string& flag, const std::string& text, const std::string& allowed, Parse parse)
    -> decltype(parse(text))
{
    try {
        return parse(text);
    } catch (const ggxcl::InvalidArgument&) {
        throw UsageError(flag, text, allowed);
    }
}

// The library's methods, precision modes and transports named by `flag`.
inline ggxcl::Method parse_method_option(const std::string& flag, const std::string& text)
{
    return parsed_option(flag, text, "one of " + ggxcl::method_list(), ggxcl::parse_method);
}
inline ggxcl::Precision parse_precision_option(const std::string& flag, const std::string& text)
{
    return parsed_option(flag, text, "one of " + ggxcl::precision_list(), ggxcl::parse_precision);
}
inline ggxcl::Transport parse_transport_option(const std::string& flag, const std::string& text)
{
    return parsed_option(flag, text, "one of radiance, importance", ggxcl::parse_transport);
}

} // namespace ggxapp
