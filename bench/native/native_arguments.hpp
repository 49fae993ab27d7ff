// native_arguments.hpp - strict parsing of ggx-native's positional arguments: whole numbers
// within bounds, finite floats (printed by ggx bench with 9 significant digits, so they read
// back to the same float), unit tangent-space views, and method and job names.  Anything else
// throws UsageError naming the argument, the value and what is allowed.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "native_baseline.hpp"

namespace ggxnative {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

int parse_method(const std::string& text);     // a method's name -> its GGX_METHOD_* id
Job parse_job(const std::string& text);        // write_m_pdf_m, furnace_sum, world_space_o
std::uint64_t parse_whole(const char* name, const std::string& text, std::uint64_t low, std::uint64_t high);
float parse_float(const char* name, const std::string& text, float low, float high);
// Three components of a unit vector (length within 1e-3 of 1) with z >= 0.
void parse_view(const std::string& x, const std::string& y, const std::string& z, float view[3]);

}  // namespace ggxnative
