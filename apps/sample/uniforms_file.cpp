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

std::string row_text(std::size_t row, const double* values, std::size_t columns)
{
    std::ostringstream out;
    out.precision(17);
    out << "row " << row << ": ";
    for (std::size_t c = 0; c < columns; ++c)
        out << (c ? "," : "") << values[c];
    return out.str();
}

} // namespace

void read_uniforms(const std::string& path, bool dielectric, ggxcl::PerSampleInputs& inputs)
{
    const std::size_t columns = dielectric ? 3 : 2;
    const std::string shape = dielectric ? "(N, 3) (u1, u2 and the lobe's u3, with --eta)" : "(N, 2)";
    NpyDoubles array;
    try {
        array = read_npy_doubles(path);
    } catch (const std::runtime_error& e) {
        throw UsageError("--uniforms", path, "a float32 or float64 .npy of shape " + shape + ": " + e.what());
    }
    if (array.columns != columns || array.rows == 0)
        throw UsageError("--uniforms", path,
                         "a .npy of shape " + shape + " with N >= 1, not (" + std::to_string(array.rows) + ", " +
                             std::to_string(array.columns) + ")");
    inputs.uniforms.resize(array.rows);
    inputs.lobe_uniforms.resize(dielectric ? array.rows : 0);
    for (std::size_t j = 0; j < array.rows; ++j) {
        const double* row = array.data.data() + columns * j;
        for (std::size_t c = 0; c < columns; ++c)
            if (!(row[c] >= 0.0 && row[c] < 1.0))
                throw UsageError("--uniforms", path + " " + row_text(j, row, columns),
                                 "rows of " + std::to_string(columns) + " numbers in [0, 1)");
        inputs.uniforms[j] = {ggxcl::uniform_to_float(row[0]), ggxcl::uniform_to_float(row[1])};
        if (dielectric)
            inputs.lobe_uniforms[j] = ggxcl::uniform_to_float(row[2]);
    }
}

} // namespace ggxapp
