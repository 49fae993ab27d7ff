// ggx_bin_mass.hpp - integral of a density on the unit sphere over bins of equal solid angle
// (internal helper of the bin probabilities of o and of m). The density's support is described by
// the curves where it jumps or has a kink and by one point where it may be singular; the
// integration cuts there, so each bin converges to the rounding level.
#pragma once

#include <functional>
#include <vector>

#include "ggx_curve.hpp"
#include "ggx_reference.hpp"

namespace ggxref::detail {

// Where a density jumps or has a corner (edges), and where it may grow like 1 / distance (point).
struct Support {
    std::vector<SphereCurve> edges;
    bool has_point = false;
    double point_theta = 0.0, point_phi = 0.0;
};

// The circle of unit w with w.axis = height.
std::function<Vec3(double)> circle(const Vec3& axis, double height);
// The normals on the edge of the bounded cap: m = normalize(ax mh.x, ay mh.y, mh.z) with mh = c + ih
// and c on the circle c.z = -k ih.z (Eto-Tokuyoshi; tangent space, iz > 0).
std::function<Vec3(double)> bounded_cap_normals(const Params&);
// A point of the support: records its polar angle and azimuth when it is off the z axis.
void set_point(Support&, const Vec3& point);

// int density dw over each bin: z = cos theta in [-1, 1] split uniformly into nz, phi = atan2(y, x)
// in [0, 2 pi) into nphi; index = iz_bin * nphi + iphi_bin. rel_tol is the per-panel acceptance
// of the adaptive quadrature.
std::vector<double> bin_masses(const std::function<double(const Vec3&)>& density, const Support&, int nz, int nphi,
                               double rel_tol);

}  // namespace ggxref::detail
