// ggx_quadrature.hpp - deterministic integrals of the reference pdfs: normalization, accepted mass,
// the bounded-cap mass, directional albedo, and per-bin probabilities of o and of m for chi-square
// tests.
#pragma once

#include <vector>

#include "ggx_reference.hpp"

namespace ggxref {

double integrate_pdf_o(Method, const Params&);        // int over the sphere of pdf_o (1 for every method)
double integrate_pdf_o_upper(Method, const Params&);  // int over oz > 0 (oz = o.n for caps_iso): accepted mass
double bounded_cap_mass_of_caps(const Params&);       // caps pdf mass inside the bounded cap = 1 - (1-k) iz/(iz+t)
// E(i) = int_{oz > 0} D(h) G2hc(i, o) / (4 iz) do. Tangent space when n = (0, 0, 1); otherwise the
// surface is taken as isotropic (alpha = ax) about n, as caps_iso sees it.
double albedo(const Params&);

// Probability of o per bin of equal solid angle: z = cos(theta) in [-1, 1] split uniformly into nz,
// phi = atan2(y, x) in [0, 2 pi) into nphi; index = iz_bin * nphi + iphi_bin. o in world
// coordinates for caps_iso. rel_tol is the per-panel acceptance of the adaptive quadrature.
std::vector<double> bin_probabilities(Method, const Params&, int nz, int nphi);
std::vector<double> bin_probabilities(Method, const Params&, int nz, int nphi, double rel_tol);
// Probability of the sampled microfacet normal m per bin (same binning as bin_probabilities; world
// coordinates for caps_iso), from pdf_m: D(m) mz for ndf, the VNDF Dv(m; i) for heitz, heitz2017, caps
// and caps_iso, and the bounded VNDF 2 D(m) max(0, i.m) / (k iz + t) restricted to the bounded cap for
// bounded. Each sums to 1; m.n > 0, so for n = z only the upper half of the z bins is non-zero.
std::vector<double> bin_probabilities_m(Method, const Params&, int nz, int nphi);
std::vector<double> bin_probabilities_m(Method, const Params&, int nz, int nphi, double rel_tol);

}  // namespace ggxref
