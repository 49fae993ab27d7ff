// cli_errors.cpp - CLI11's parse errors in the tool's own words.
#include "cli_errors.hpp"

#include <algorithm>
#include <regex>
#include <vector>

namespace ggxapp {

namespace {

// Levenshtein distance: the edits that turn `a` into `b`.
std::size_t edit_distance(const std::string& a, const std::string& b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// The listed commands of `app` (not the hidden ones), in order.
std::vector<std::string> command_names(const CLI::App& app)
{
    std::vector<std::string> names;
    for (const CLI::App* command : app.get_subcommands([](const CLI::App* c) { return !c->get_group().empty(); }))
        names.push_back(command->get_name());
    return names;
}

std::string joined(const std::vector<std::string>& names)
{
    std::string text;
    for (const std::string& name : names)
        text += (text.empty() ? "" : ", ") + name;
    return text;
}

// "; did you mean 'X'?" for the candidate nearest `given`, when it is near enough.
std::string nearest_of(const std::string& given, const std::vector<std::string>& candidates)
{
    std::string best;
    std::size_t best_distance = 3;  // at most 2 edits
    for (const std::string& candidate : candidates) {
        const std::size_t d = edit_distance(given, candidate);
        if (d < best_distance)
            best = candidate, best_distance = d;
    }
    return best.empty() ? "" : "; did you mean '" + best + "'?";
}

// The long names of the options of the command being parsed (the first one given, else the app's).
std::vector<std::string> option_names(const CLI::App& app)
{
    const CLI::App* command = &app;
    for (const CLI::App* sub : app.get_subcommands({}))
        if (sub->parsed())
            command = sub;
    std::vector<std::string> names;
    for (const CLI::Option* option : command->get_options())
        for (const std::string& name : option->get_lnames())
            names.push_back("--" + name);
    return names;
}

} // namespace

std::optional<std::string> unknown_command(const CLI::App& app, int argc, char** argv)
{
    if (argc < 2 || argv[1][0] == '-')
        return std::nullopt;
    const std::string given = argv[1];
    const std::vector<std::string> names = command_names(app);
    for (const CLI::App* command : app.get_subcommands({}))
        if (command->check_name(given))
            return std::nullopt;
    return "unknown command '" + given + "'" + nearest_of(given, names) + " (the commands: " + joined(names) + ")";
}

std::string parse_error_message(const CLI::ParseError& error, const CLI::App& app)
{
    const std::string what = error.what();
    std::smatch m;
    if (std::regex_match(what, m, std::regex("(\\S+): At Most 1 required but received (\\d+)")))
        return m[1].str() + ": given " + m[2].str() + " times; allowed is once";
    if (std::regex_match(what, m, std::regex("(\\S+): \\d+ required \\S+ missing")))
        return m[1].str() + ": its value is missing";
    if (std::regex_search(what, m, std::regex("not expected: (.*)$"))) {
        // CLI11 lists the extras in no fixed order: name an option among them first.
        std::string extra, all = m[1].str();
        std::smatch word;
        for (auto at = all.cbegin(); std::regex_search(at, all.cend(), word, std::regex("\\S+")); at = word[0].second)
            if (extra.empty() || (extra[0] != '-' && word.str()[0] == '-'))
                extra = word.str();
        return (extra[0] == '-' ? "unknown option '" : "unexpected argument '") + extra + "'" +
               nearest_of(extra, option_names(app)) + " (see the command's --help)";
    }
    if (what == "A subcommand is required")
        return "a command is required: one of " + joined(command_names(app)) + " (see ggx --help)";
    std::string text = what;
    if (!text.empty())
        text[0] = char(std::tolower(static_cast<unsigned char>(text[0])));
    return text + " (see ggx --help)";
}

} // namespace ggxapp
