// png_file.hpp - a table of values in [0, 1] as an 8-bit grey PNG, each
// cell a square of `scale` pixels: row r of the table is pixel row r (top
// to bottom), column c pixel column c (left to right).
#pragma once

#include <string>
#include <vector>

namespace albedo {

// Written under a temporary name and renamed; throws std::runtime_error on failure.
void write_png(const std::string& path, const std::vector<float>& values, int rows, int columns, int scale);

} // namespace albedo
