// ggx_bins_m.cpp - probability of the sampled microfacet normal m per bin of equal solid angle
// (the binning of ggx_bins.cpp): pdf_m integrated by ggx_bin_mass over its support. pdf_m is
// bounded, so there is no singular point; its edges are the horizon m.n = 0, the visibility circle
// i.m = 0 and the edge of the bounded cap.
#include <cmath>

#include "ggx_bin_mass.hpp"
#include "ggx_quadrature.hpp"

namespace ggxref {
namespace {

using detail::Support;

// NDF sampling: D(m) mz, a kink at mz = 0. VNDF (docs/MATH.md "Shared quantities"): 2 D(m) max(0, i.m) / (iz + t)
// jumps at m.n = 0 where i.m > 0 and has a kink at i.m = 0. The bounded sampler above the
// horizon draws only inside its cap, which lies strictly within m.n > 0 and i.m > 0
// (mh.z >= (1 - k) ih.z > 0 and ih.mh > 0), so its one edge, a jump, is the cap's.
Support support_m_of(Method method, const Params& p)
{
    Support s;
    const Vec3 n = method == Method::caps_iso ? normalize(p.n) : Vec3{0.0, 0.0, 1.0};
    const Vec3 i = normalize(p.i);
    if (method == Method::bounded && i.z > 0.0 && bounded_k(p.i, p.ax, p.ay) < 1.0) {
        s.edges.emplace_back(detail::bounded_cap_normals(p));
        return s;
    }
    s.edges.emplace_back(detail::circle(n, 0.0));
    if (method != Method::ndf && std::fabs(dot(i, n)) < 1.0)
        s.edges.emplace_back(detail::circle(i, 0.0));
    return s;
}

}  // namespace

std::vector<double> bin_probabilities_m(Method method, const Params& p, int nz, int nphi, double rel_tol)
{
    auto pdf = [&](const Vec3& m) { return pdf_m(method, p, m); };
    return detail::bin_masses(pdf, support_m_of(method, p), nz, nphi, rel_tol);
}

std::vector<double> bin_probabilities_m(Method method, const Params& p, int nz, int nphi)
{
    return bin_probabilities_m(method, p, nz, nphi, 1e-8);
}

}  // namespace ggxref
