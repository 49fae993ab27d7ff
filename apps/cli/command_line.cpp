// command_line.cpp - the command line as typed, kept for reports.
#include <string>

#include "commands.hpp"

namespace ggxapp {

namespace {
std::string& stored()
{
    static std::string text;
    return text;
}
} // namespace

void remember_command_line(int argc, char** argv)
{
    std::string text = "ggx";
    for (int k = 1; k < argc; ++k) {
        std::string word = argv[k];
        bool plain = word.find_first_of(" \t'\"$&|;<>()*?") == std::string::npos && !word.empty();
        text += " " + (plain ? word : "'" + word + "'");
    }
    stored() = text;
}

const std::string& command_line()
{
    return stored();
}

} // namespace ggxapp
