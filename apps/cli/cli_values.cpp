// cli_values.cpp - strict parsers for CLI values (whole string, finite numbers).
#include "cli_values.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <unistd.h>
#include <limits>
#include <sstream>
#include <vector>

#include <ggxcl/params.hpp>

#include "library_errors.hpp"

namespace ggxapp {

namespace {

// The whole of `text` as a finite double, else nothing.
bool to_double(const std::string& text, double& value)
{
    if (text.empty())
        return false;
    std::size_t used = 0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        return false;
    }
    return used == text.size() && std::isfinite(value);
}

} // namespace

std::vector<std::string> split_list(const std::string& text, char separator)
{
    std::vector<std::string> parts;
    std::stringstream stream(text);
    std::string part;
    while (std::getline(stream, part, separator))
        parts.push_back(part);
    if (!text.empty() && text.back() == separator)
        parts.push_back("");
    return parts;
}

std::array<float, 2> parse_alpha(const std::string& flag, const std::string& text)
{
    const std::string allowed = std::string("one or two numbers, as AX or AX,AY, each ") + ggxcl::alpha_range;
    std::vector<std::string> parts = split_list(text, ',');
    if (parts.empty() || parts.size() > 2)
        throw UsageError(flag, text, allowed);
    double values[2];
    for (std::size_t k = 0; k < parts.size(); ++k)
        if (!to_double(parts[k], values[k]))
            throw UsageError(flag, text, allowed);
    return {float(values[0]), float(values[parts.size() - 1])};  // the library checks the range
}

double parse_number(const std::string& flag, const std::string& text)
{
    double value;
    if (!to_double(text, value))
        throw UsageError(flag, text, "a number");
    return value;
}

std::array<float, 3> parse_vec3(const std::string& flag, const std::string& text)
{
    const std::string allowed = "three finite numbers X,Y,Z, not all 0 (a direction)";
    std::vector<std::string> parts = split_list(text, ',');
    double v[3];
    if (parts.size() != 3 || !to_double(parts[0], v[0]) || !to_double(parts[1], v[1]) || !to_double(parts[2], v[2]) ||
        (v[0] == 0 && v[1] == 0 && v[2] == 0))
        throw UsageError(flag, text, allowed);
    // Only the direction matters: normalize in double (scaled first, so 1e300 or 1e-300 components
    // neither overflow nor vanish in float; found by fuzz/fuzz_values).
    double largest = std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])});
    for (double& c : v)
        c /= largest;
    double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {float(v[0] / length), float(v[1] / length), float(v[2] / length)};
}

std::uint64_t parse_count(const std::string& flag, const std::string& text)
{
    const std::string allowed = "a whole number from 1 to 2^63, written as 1000, 1e6 or 2^24";
    double value = 0;
    std::size_t caret = text.find('^');
    if (caret != std::string::npos) {
        double base, exponent;
        if (!to_double(text.substr(0, caret), base) || !to_double(text.substr(caret + 1), exponent))
            throw UsageError(flag, text, allowed);
        value = std::pow(base, exponent);
    } else if (!to_double(text, value)) {
        throw UsageError(flag, text, allowed);
    }
    if (!(value >= 1.0) || value > 9.2233720368547758e18 || value != std::floor(value))
        throw UsageError(flag, text, allowed);
    return std::uint64_t(value);
}

std::uint64_t parse_uint64(const std::string& flag, const std::string& text)
{
    const std::string allowed = "a whole number from 0 to 2^64-1";
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError(flag, text, allowed);
    try {
        return std::stoull(text);
    } catch (const std::exception&) {
        throw UsageError(flag, text, allowed);
    }
}

std::uint64_t parse_whole(const std::string& flag, const std::string& text, std::uint64_t low, std::uint64_t high)
{
    const std::string allowed = "a whole number from " + std::to_string(low) + " to " + std::to_string(high);
    if (text.empty() || text.size() > 19 || text.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError(flag, text, allowed);
    std::uint64_t value = std::stoull(text);
    if (value < low || value > high)
        throw UsageError(flag, text, allowed);
    return value;
}

// Comma-separated names, each one of `allowed` ("all": every one).
std::vector<std::string> parse_name_list(const std::string& flag, const std::string& text,
                                    const std::vector<std::string>& allowed)
{
    if (text == "all")
        return allowed;
    std::string joined;
    for (const std::string& a : allowed)
        joined += (joined.empty() ? "" : ", ") + a;
    const std::vector<std::string> names = split_list(text);
    for (const std::string& name : names)
        if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
            throw UsageError(flag, text, "a comma-separated list of " + joined + " (or all)");
    if (names.empty())
        throw UsageError(flag, text, "a comma-separated list of " + joined + " (or all)");
    return names;
}

double parse_level(const std::string& flag, const std::string& text)
{
    double value;
    if (!to_double(text, value) || !(value > 0.0 && value < 1.0))
        throw UsageError(flag, text, "a significance level between 0 and 1, e.g. 0.01");
    return value;
}

void check_writable_folder(const std::string& flag, const std::string& path)
{
    std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (folder.empty())
        folder = ".";
    std::error_code error;
    std::filesystem::create_directories(folder, error);  // as `ggx demo` always has: a fresh folder is made
    bool is_folder = std::filesystem::is_directory(folder, error);
    if (!is_folder || ::access(folder.c_str(), W_OK) != 0)
        throw UsageError(flag, path, "a path in a writable folder (made when missing)");
}

float parse_eta(const std::string& flag, const std::string& text)
{
    const float eta = float(parse_number(flag, text));
    ggxcl::SampleParams conductor;  // a method with a dielectric sampler: the library's rule for eta alone
    conductor.eta = eta;
    in_option_terms({{"eta", {flag, text}}}, [&] { ggxcl::validate(conductor); });
    return eta;
}

double parse_angle(const std::string& flag, const std::string& text, double low, double high)
{
    double value;
    if (!to_double(text, value) || value < low || value > high) {
        std::ostringstream allowed;
        allowed << "degrees from " << low << " to " << high;
        throw UsageError(flag, text, allowed.str());
    }
    return value;
}

} // namespace ggxapp
