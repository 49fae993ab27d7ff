// ggx_bins.cpp - probability of o per bin of equal solid angle (z = cos theta, phi), for chi-square
// tests of sampled histograms: pdf_o integrated by ggx_bin_mass over its support, whose edge is a
// jump, with o = -i as the singular point.
#include <cmath>

#include "ggx_bin_mass.hpp"
#include "ggx_quadrature.hpp"

namespace ggxref {
namespace {

using detail::SphereCurve;
using detail::Support;

// Edge of the bounded cap: the stretched reflections ohat with ohat.z = -k ih.z, carried to o.
std::function<Vec3(double)> bounded_edge(const Params& p)
{
    const std::function<Vec3(double)> normals = detail::bounded_cap_normals(p);
    return [=](double psi) { return reflect(p.i, normals(psi)); };
}

// NDF sampling has full support; the caps family is supported on o.n > -i.n, except the bounded
// sampler above the horizon, whose support is the image of its cap. Near o = -i the NDF-sampling
// pdf grows like 1 / |i + o| and the others have a corner.
Support support_of(Method method, const Params& p)
{
    Support s;
    const Vec3 n = method == Method::caps_iso ? p.n : Vec3{0.0, 0.0, 1.0};
    const double iz = dot(p.i, n);
    if (method == Method::bounded && iz > 0.0 && bounded_k(p.i, p.ax, p.ay) < 1.0)
        s.edges.emplace_back(bounded_edge(p));
    else if (method != Method::ndf && std::fabs(iz) < 1.0)
        s.edges.emplace_back(detail::circle(n, -iz));
    detail::set_point(s, -p.i);
    return s;
}

}  // namespace

std::vector<double> bin_probabilities(Method method, const Params& p, int nz, int nphi, double rel_tol)
{
    auto pdf = [&](const Vec3& o) { return pdf_o(method, p, o); };
    return detail::bin_masses(pdf, support_of(method, p), nz, nphi, rel_tol);
}

std::vector<double> bin_probabilities(Method method, const Params& p, int nz, int nphi)
{
    return bin_probabilities(method, p, nz, nphi, 1e-8);
}

}  // namespace ggxref
