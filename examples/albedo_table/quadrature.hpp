// quadrature.hpp - the directional albedo of isotropic GGX in double
// precision, independent of the device: E(i) = integral over the upper
// hemisphere of f(i, o) o.z do, with the height-correlated Smith G2 and
// Fresnel 1 (the white furnace).
#pragma once

namespace albedo {

// E for the view (view_x, 0, view_z) (normalized here) and roughness alpha.
double albedo_quadrature(double view_x, double view_z, double alpha);

} // namespace albedo
