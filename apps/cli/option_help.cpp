// option_help.cpp - the kinds of the options' values in --help.
#include "option_help.hpp"

#include <map>
#include <string>

namespace ggxapp {

namespace {

// The kind of value of each option, by its long name; any other option shows VALUE.
const std::map<std::string, std::string>& value_kinds()
{
    static const std::map<std::string, std::string> kinds = {
        {"count", "COUNT"},          {"first", "INDEX"},        {"seed", "SEED"},
        {"alpha", "AX[,AY]"},        {"alphas", "LIST"},        {"theta", "DEGREES"},
        {"thetas", "LIST"},          {"phi", "DEGREES"},        {"normal", "X,Y,Z"},
        {"eta", "INDEX-RATIO"},      {"method", "METHOD"},      {"methods", "LIST"},
        {"sampler", "FILE"},         {"sampler-name", "NAME"},  {"precision", "MODE"},
        {"precisions", "LIST"},      {"sequence", "NAME"},      {"sequences", "LIST"},
        {"transport", "MODE"},       {"device", "DEVICE"},      {"devices", "LIST"},
        {"out", "PATH"},             {"csv", "PATH"},           {"markdown", "PATH"},
        {"html", "PATH"},            {"charts", "PATH"},        {"manifest", "PATH"},
        {"uniforms", "FILE"},        {"fields", "LIST"},        {"shard", "R/S|auto"},
        {"check", "LEVEL"},          {"against", "METHOD"},     {"of", "o|m"},
        {"bins-z", "COUNT"},         {"bins-phi", "COUNT"},     {"repeats", "COUNT"},
        {"threads", "COUNT"},        {"jobs", "LIST"},          {"integrands", "LIST"},
        {"min-n", "2^K"},            {"max-n", "2^K"},          {"randomizations", "COUNT"},
        {"speed-n", "COUNT"},        {"histogram-n", "COUNT"},  {"native-count", "COUNT"},
        {"cell-samples", "COUNT"},   {"page-points", "COUNT"},  {"budget-ms", "MS"},
        {"scene", "NAME"},           {"reproduces", "PATH"}};
    return kinds;
}

void describe(CLI::Option& option)
{
    if (option.get_items_expected_max() == 0)
        return;  // a flag
    const std::vector<std::string>& names = option.get_lnames();
    const auto kind = names.empty() ? value_kinds().end() : value_kinds().find(names.front());
    option.type_name(kind != value_kinds().end() ? kind->second : "VALUE");
    option.capture_default_str();
    if (option.get_default_str() == "[]")  // a repeatable option given no value
        option.default_str("");
}

} // namespace

void describe_option_values(CLI::App& app)
{
    for (CLI::Option* option : app.get_options())
        describe(*option);
    for (CLI::App* command : app.get_subcommands({}))
        describe_option_values(*command);
}

} // namespace ggxapp
