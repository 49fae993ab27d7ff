// npy_file.cpp - the .npy header ("\x93NUMPY", version 1.0, a Python dict
// literal padded with spaces so the data starts at a multiple of 64 bytes)
// followed by the raw little-endian floats.
#include "npy_file.hpp"

#include <cstdint>
#include <fstream>

#include "atomic_file.hpp"

namespace albedo {

namespace {

std::string npy_header(int rows, int columns)
{
    std::string dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + std::to_string(rows) + ", " +
                       std::to_string(columns) + "), }";
    const std::size_t fixed = 10;  // magic (6), version (2), header length (2)
    while ((fixed + dict.size() + 1) % 64 != 0)
        dict += ' ';
    dict += '\n';
    const std::uint16_t length = static_cast<std::uint16_t>(dict.size());
    return std::string("\x93NUMPY\x01\x00", 8) + char(length & 0xff) + char(length >> 8) + dict;
}

} // namespace

void write_npy(const std::string& path, const std::vector<float>& values, int rows, int columns)
{
    static_assert(sizeof(float) == 4, "float32");
    write_atomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        const std::string header = npy_header(rows, columns);
        out.write(header.data(), header.size());
        // '<f4': the host's floats as they are, little-endian on x86 and ARM.
        out.write(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
        return bool(out.flush());
    });
}

} // namespace albedo
