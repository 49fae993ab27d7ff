// ggx_integrals.hpp - exact (quadrature) reflected radiance of the GGX BRDF under simple lights,
// the ground truth of Monte Carlo convergence measurements: I(i, L) = int_{oz > 0} brdf_cos(i, o)
// L(o) do in tangent space (n = (0, 0, 1)), for a uniform light (the albedo), a cosine-power lobe
// and a small disk light.
#pragma once

#include "ggx_reference.hpp"

namespace ggxref {

struct Light {
    enum class Kind { uniform, lobe, disk } kind = Kind::uniform;  // uniform: L = 1 (the albedo)
    Vec3 l{0, 0, 1};        // unit direction of the lobe or the disk's center
    double exponent = 0.0;  // lobe: L(o) = max(0, o.l)^exponent
    double radius = 0.0;    // disk: angular radius in radians, L(o) = [o.l >= cos radius]
};

// L(o) for a unit o. Lobe: 0 for o.l <= 0 (also at exponent 0: the lobe is the hemisphere
// o.l > 0), max(0, o.l)^exponent otherwise; disk: 1 on the closed disk o.l >= cos(radius).
double light_value(const Light& light, const Vec3& o);

// I(i, L) above: tangent space (params.n is not read), anisotropic alpha allowed, 0 for iz <= 0.
// Relative accuracy 1e-9 or better (absolute 1e-12 for tiny values) for alpha in [0.01, 2] and
// views up to 89 degrees. Needs a unit l, exponent >= 0 and 0 < radius <= pi/2; NaN otherwise.
double reflected_radiance(const Params& params, const Light& light);

}  // namespace ggxref
