// stress_grid.hpp - the inputs of the stability map (`ggx stress`): for
// every roughness row (alpha 1e-7 .. 1e2, log) and view column (theta 0 ..
// 180 degrees with exactly 0, 90 and 180 and the grazing cos theta 1e-4 and
// 1e-7), cases with roughness pairs (alpha, alpha), anisotropy 1:1000 both
// ways and one axis exactly 0 (caps-iso: isotropic, but normals over the
// sphere including exactly (0, 0, -1)), each with uniforms at the edges of
// [0, 1) (0, 1/2, 1 - 2^-24 and their pairs), random ones, and the pair
// that puts the caps family's cap point nearest -v (u2 = 1 - 2^-24, u1 at
// the azimuth of -v), where h = c + v cancels.
#pragma once

#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace ggxapp {

struct StressCase {
    float ax, ay;
    ggxcl::Vec3 view, normal;
    float u1, u2;
    int row, column;  // alpha row, theta column of the map
};

struct StressAxes {
    std::vector<double> alphas;         // row values
    std::vector<double> cos_theta;      // column values: cosine of the view's angle from the normal
    std::vector<double> theta_degrees;  // the same angles in degrees (exactly 0, 90, 180 where cos is 1, 0, -1)
};

StressAxes stress_axes();
std::vector<StressCase> stress_cases(ggxcl::Method method, const StressAxes& axes);

} // namespace ggxapp
