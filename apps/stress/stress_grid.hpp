// stress_grid.hpp - the inputs of the stability map (`ggx stress`): for
// every roughness row (alpha 1e-7 .. 1e2, log) and view column (theta 0 ..
// 180 degrees with exactly 0, 90 and 180 and the grazing cos theta 1e-4 and
// 1e-7), cases with roughness pairs (alpha, alpha), anisotropy 1:1000 both
// ways and one axis exactly 0 (caps-iso: isotropic, but normals over the
// sphere including exactly (0, 0, -1)), each with uniforms at the edges of
// [0, 1) (0, 1/2, 1 - 2^-24 and their pairs), random ones, and the pair
// that puts the caps family's cap point nearest -v (u2 = 1 - 2^-24, u1 at
// the azimuth of -v), where h = c + v cancels.
// The rough dielectric's map (dielectric_cases) takes the same rows and
// pairs over views from both sides of the surface, for each relative index
// eta of its axes, with a third uniform (the lobe's) at 0, inside and at
// 1 - 2^-24.
#pragma once

#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace ggxapp {

struct StressCase {
    float ax, ay;
    ggxcl::Vec3 view, normal;
    float u1, u2;
    int row, column;              // alpha row, theta column of the map
    float u3 = 0.0f, eta = 0.0f;  // a dielectric's lobe uniform and relative index (0: a conductor)
    bool random = false;          // uniforms drawn at random (not the edge and rim pairs)
};

struct StressAxes {
    std::vector<double> alphas;         // row values
    std::vector<double> cos_theta;      // column values: cosine of the view's angle from the normal
    std::vector<double> theta_degrees;  // the same angles in degrees (exactly 0, 90, 180 where cos is 1, 0, -1)
    std::vector<float> etas;            // a dielectric map's relative indices, a layer of cells each; empty for conductors
};

StressAxes stress_axes();
// `isotropic`: the pairs (alpha, alpha) alone, as for caps-iso (`ggx stress --isotropic-samplers`:
// a user sampler of an isotropic surface meets no other).
std::vector<StressCase> stress_cases(ggxcl::Method method, const StressAxes& axes, bool isotropic = false);

// The indices `ggx stress --eta all` runs: near 1 from both sides (1 - 2^-24, 1 + 2^-23, 1 -+ 1e-4),
// typical (1/1.5, 1.33, 1.5, 2.4) and extreme (1e-3, 10, 100).
std::vector<float> dielectric_etas();
// The dielectric map's axes: stress_axes' roughness rows, views from above and below (grazing at
// cos theta = +-1e-4, +-1e-7, exactly 0, the poles exactly, both sides of the critical angles of
// 1.5 and 1/1.5), and `etas`.
StressAxes dielectric_axes(const std::vector<float>& etas);
// Every eta of the axes, each with stress_cases' roughness pairs (normals for caps-iso) and 54
// uniform triples: each pair of stress_cases (the rim pair for the view seen from above, as the
// dielectric samples it) with u3 = 0, 1/2 (random for the random pairs) and 1 - 2^-24.
std::vector<StressCase> dielectric_cases(ggxcl::Method method, const StressAxes& axes);

} // namespace ggxapp
