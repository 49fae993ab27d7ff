// uniforms_file.cpp - reading and checking `ggx sample --uniforms`.
#include "uniforms_file.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <ggxcl/ggxcl.hpp>

#include "cli_values.hpp"
#include "npy_file.hpp"

namespace ggxapp {

namespace {

std::string row_text(std::size_t row, double u1, double u2)
{
    std::ostringstream out;
    out.precision(17);
    out << "row " << row << ": " << u1 << "," << u2;
    return out.str();
}

} // namespace

std::vector<std::array<float, 2>> read_uniforms(const std::string& path)
{
    NpyDoubles array;
    try {
        array = read_npy_doubles(path);
    } catch (const std::runtime_error& e) {
        throw UsageError("--uniforms", path, std::string("a float32 or float64 .npy of shape (N, 2): ") + e.what());
    }
    if (array.columns != 2 || array.rows == 0)
        throw UsageError("--uniforms", path,
                         "a .npy of shape (N, 2) with N >= 1, not (" + std::to_string(array.rows) + ", " +
                             std::to_string(array.columns) + ")");
    std::vector<std::array<float, 2>> rows(array.rows);
    for (std::size_t j = 0; j < rows.size(); ++j) {
        double u1 = array.data[2 * j], u2 = array.data[2 * j + 1];
        if (!(u1 >= 0.0 && u1 < 1.0 && u2 >= 0.0 && u2 < 1.0))
            throw UsageError("--uniforms", path + " " + row_text(j, u1, u2), "rows of two numbers in [0, 1)");
        rows[j] = {ggxcl::uniform_to_float(u1), ggxcl::uniform_to_float(u2)};
    }
    return rows;
}

} // namespace ggxapp
