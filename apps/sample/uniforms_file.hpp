// uniforms_file.hpp - `ggx sample --uniforms FILE.npy`: the caller's two
// uniforms per sample, read from a float32 or float64 .npy of shape (N, 2)
// and checked row by row before any device is opened.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace ggxapp {

// Rows (u1, u2) of `path`, each in [0, 1).  float64 values are rounded to
// the nearest float; one below 1 that rounds up to 1 becomes the largest
// float below 1 (0.99999994), so that every uniform of [0, 1) stays in it.
// Throws UsageError naming --uniforms (the file, its shape, or the first
// bad row with its values).
std::vector<std::array<float, 2>> read_uniforms(const std::string& path);

} // namespace ggxapp
