// fuzz_values.cpp - libFuzzer target: the parsers of the CLI's values
// (roughness, vectors, counts, seeds, whole numbers in a range, angles,
// levels) on any text.  Each must return a value within what it promises or
// throw UsageError naming the flag; the first byte picks the parser.
#include <cmath>
#include <cstdint>
#include <string>

#include "cli_values.hpp"

namespace {

void check(bool ok)
{
    if (!ok)
        __builtin_trap();
}

void parse_one(unsigned which, const std::string& text)
{
    using namespace ggxapp;
    switch (which % 7) {
    case 0: {
        std::array<float, 2> a = parse_alpha("--alpha", text);  // numbers; their range is the library's
        check(!std::isnan(a[0]) && !std::isnan(a[1]));
        break;
    }
    case 1: {
        std::array<float, 3> v = parse_vec3("--normal", text);
        check(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) &&
              (v[0] != 0 || v[1] != 0 || v[2] != 0));
        break;
    }
    case 2: check(parse_count("-n", text) >= 1); break;
    case 3: parse_uint64("--seed", text); break;
    case 4: {
        std::uint64_t n = parse_whole("--repeats", text, 5, 101);
        check(n >= 5 && n <= 101);
        break;
    }
    case 5: {
        double a = parse_angle("--theta", text, 0.0, 180.0);
        check(a >= 0.0 && a <= 180.0);
        break;
    }
    default: {
        double level = parse_level("--check", text);
        check(level > 0.0 && level < 1.0);
    }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size == 0)
        return 0;
    try {
        parse_one(data[0], std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
    } catch (const ggxapp::UsageError& e) {
        check(std::string(e.what()).find("--") != std::string::npos || std::string(e.what()).find("-n") == 0);
    }
    return 0;
}
