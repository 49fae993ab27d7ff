// ggx_dielectric_bins.cpp - the probability of a dielectric sample's o per bin of the whole sphere:
// dielectric_pdf_o integrated over o by ggx_bin_mass, cut at the edges of ggx_dielectric_support.
#include "ggx_bin_mass.hpp"
#include "ggx_dielectric.hpp"
#include "ggx_dielectric_side.hpp"
#include "ggx_dielectric_support.hpp"

namespace ggxref {

std::vector<double> dielectric_bin_probabilities(Method method, const Params& p, double eta, int nz, int nphi,
                                                 double rel_tol)
{
    if (method == Method::bounded || !detail::eta_ok(eta))
        return std::vector<double>(size_t(nz) * size_t(nphi), 0.0);
    auto pdf = [&](const Vec3& o) { return dielectric_pdf_o(method, p, eta, o); };
    return detail::bin_masses(pdf, detail::dielectric_support(method, p, eta), nz, nphi, rel_tol);
}

std::vector<double> dielectric_bin_probabilities(Method method, const Params& p, double eta, int nz, int nphi)
{
    return dielectric_bin_probabilities(method, p, eta, nz, nphi, 1e-8);
}

}  // namespace ggxref
