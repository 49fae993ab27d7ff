// uniforms_file.hpp - `ggx sample --uniforms FILE.npy`: the caller's two
// uniforms per sample (three for a dielectric, --eta), read from a float32
// or float64 .npy of shape (N, 2) or (N, 3) and checked row by row before
// any device is opened.
#pragma once

#include <string>

#include <ggxcl/params.hpp>

namespace ggxapp {

// Rows (u1, u2) of `path` into inputs.uniforms, and with `dielectric` their
// third column u3 into inputs.lobe_uniforms, each in [0, 1).  float64 values
// are rounded to the nearest float; one below 1 that rounds up to 1 becomes
// the largest float below 1 (0.99999994), so that every uniform of [0, 1)
// stays in it.  Throws UsageError naming --uniforms (the file, its shape, or
// the first bad row with its values).
void read_uniforms(const std::string& path, bool dielectric, ggxcl::PerSampleInputs& inputs);

} // namespace ggxapp
