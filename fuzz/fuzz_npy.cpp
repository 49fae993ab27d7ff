// fuzz_npy.cpp - libFuzzer target: the .npy reader of `ggx merge` on any
// bytes.  It must either return an array whose data its bytes hold, or
// throw std::runtime_error; anything else (a crash, a huge allocation, a
// sanitizer report, another exception) is a finding.
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "npy_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        ggxapp::NpyArray array = ggxapp::parse_npy(in, "fuzz.npy");
        if (array.data.size() != array.rows * array.columns || array.data.size() * sizeof(float) > size)
            __builtin_trap();
    } catch (const std::runtime_error&) {
    }
    return 0;
}
