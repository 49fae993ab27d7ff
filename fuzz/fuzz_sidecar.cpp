// fuzz_sidecar.cpp - libFuzzer target: the JSON sidecar reader of `ggx
// merge` on any bytes.  It must return an object with unsigned first and
// count (not wrapping past 2^64) and string columns, or throw UsageError.
#include <cstdint>
#include <sstream>
#include <string>

#include "cli_values.hpp"
#include "sidecar_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        nlohmann::json doc = ggxapp::parse_sidecar(in, "fuzz.npy");
        std::uint64_t first = doc["first"].get<std::uint64_t>(), count = doc["count"].get<std::uint64_t>();
        if (count > ~std::uint64_t(0) - first || !doc["columns"].is_array())
            __builtin_trap();
    } catch (const ggxapp::UsageError&) {
    }
    return 0;
}
