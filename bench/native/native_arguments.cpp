// native_arguments.cpp - checking ggx-native's arguments.
#include "native_arguments.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ggxnative {

namespace {

[[noreturn]] void reject(const char* name, const std::string& text, const std::string& allowed)
{
    throw UsageError(std::string(name) + " '" + text + "': " + allowed);
}

std::string number_text(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

}  // namespace

int parse_method(const std::string& text)
{
    const int method = method_id(text);
    if (method >= 0)
        return method;
    std::string names;
    for (int m = 0; m < method_count(); ++m)
        names += std::string(m == 0 ? "" : ", ") + method_name(m);
    reject("METHOD", text, "one of " + names);
}

Job parse_job(const std::string& text)
{
    for (Job j : {Job::write_m_pdf_m, Job::furnace_sum, Job::world_space_o})
        if (text == job_name(j))
            return j;
    reject("JOB", text, "write_m_pdf_m, furnace_sum or world_space_o");
}

std::uint64_t parse_whole(const char* name, const std::string& text, std::uint64_t low, std::uint64_t high)
{
    const std::string allowed = "a whole number from " + std::to_string(low) + " to " + std::to_string(high);
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        reject(name, text, allowed);
    errno = 0;
    unsigned long long value = std::strtoull(text.c_str(), nullptr, 10);
    if (errno == ERANGE || value < low || value > high)
        reject(name, text, allowed);
    return value;
}

float parse_float(const char* name, const std::string& text, float low, float high)
{
    const std::string allowed = "a number from " + number_text(low) + " to " + number_text(high);
    if (text.empty() || text.find_first_of(" \t\n") != std::string::npos)
        reject(name, text, allowed);
    char* end = nullptr;
    float value = std::strtof(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(value) || !(value >= low && value <= high))
        reject(name, text, allowed);
    return value;
}

void parse_view(const std::string& x, const std::string& y, const std::string& z, float view[3])
{
    view[0] = parse_float("VX", x, -1.0f, 1.0f);
    view[1] = parse_float("VY", y, -1.0f, 1.0f);
    view[2] = parse_float("VZ", z, 0.0f, 1.0f);
    double length = std::sqrt(double(view[0]) * view[0] + double(view[1]) * view[1] + double(view[2]) * view[2]);
    if (std::fabs(length - 1.0) > 1e-3)
        throw UsageError("VX VY VZ '" + x + " " + y + " " + z + "': a unit vector (length " + number_text(length) +
                         ") with VZ >= 0");
}

}  // namespace ggxnative
