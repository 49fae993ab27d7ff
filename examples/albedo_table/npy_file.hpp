// npy_file.hpp - a float32 array of shape (rows, columns) as a NumPy .npy
// file (format 1.0, little-endian, C order).
#pragma once

#include <string>
#include <vector>

namespace albedo {

// Written under a temporary name and renamed; throws std::runtime_error
// naming the path on failure.
void write_npy(const std::string& path, const std::vector<float>& values, int rows, int columns);

} // namespace albedo
