// cli_values.hpp - parsing of the CLI's value syntaxes: roughness
// "AX[,AY]", vectors "X,Y,Z", counts "1000", "1e6" or "2^24".  A bad value
// throws UsageError naming the flag, the value and what is allowed.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace ggxapp {

class UsageError : public std::runtime_error {
public:
    UsageError(const std::string& flag, const std::string& value, const std::string& allowed)
        : std::runtime_error(flag + ": invalid value '" + value + "': allowed is " + allowed)
    {
    }
    explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

// A test the user asked for (--check) failed: exit status 1.
class CheckFailed : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// One or two numbers "AX[,AY]"; the library checks their range (ggxcl::alpha_range).
std::array<float, 2> parse_alpha(const std::string& flag, const std::string& text);
// A finite number.
double parse_number(const std::string& flag, const std::string& text);
std::array<float, 3> parse_vec3(const std::string& flag, const std::string& text);  // returned unit length
std::uint64_t parse_count(const std::string& flag, const std::string& text);
std::uint64_t parse_uint64(const std::string& flag, const std::string& text);
std::uint64_t parse_whole(const std::string& flag, const std::string& text, std::uint64_t low, std::uint64_t high);
// Makes the folder of `path` when missing; throws UsageError unless a file can
// be created there.  Commands call it when they run, before writing.
void check_writable_folder(const std::string& flag, const std::string& path);

double parse_angle(const std::string& flag, const std::string& text, double low, double high);

// The items of `text` between separators, an empty one wherever two meet or one ends the text.
std::vector<std::string> split_list(const std::string& text, char separator = ',');

// Comma-separated names, each one of `allowed` ("all": every one, in order);
// empty items are refused.
std::vector<std::string> parse_name_list(const std::string& flag, const std::string& text,
                                         const std::vector<std::string>& allowed);

// A relative index of refraction as the library takes it (0: a conductor), its rule
// reported for `flag`.
float parse_eta(const std::string& flag, const std::string& text);

// A significance level strictly between 0 and 1.
double parse_level(const std::string& flag, const std::string& text);

} // namespace ggxapp
