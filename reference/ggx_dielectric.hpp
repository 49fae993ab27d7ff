// ggx_dielectric.hpp - the rough dielectric in the reference (Walter et al. 2007; SPEC "Rough
// dielectrics"): sampling both lobes with every method's normals, the density of o over the whole
// sphere, its exact bin probabilities, the single-scattering white furnace, and the share of the
// transmission that the bounded cap cannot reach. Included by ggx_reference.hpp.
//
// Conventions: eta = index below the surface / index above, finite, > 0 and != 1 (anything else:
// the fallback sample, densities and probabilities 0, a NaN albedo or share). A view with i.n < 0
// sees the interface from below: every function works in the frame mirrored through the surface
// (x -> x - 2 (x.n) n: z -> -z for the tangent-space methods, and for caps_iso too the view is
// mirrored about its n, rather than n turned to -n, which for n = z would be caps-iso's excluded
// normal -z) with 1/eta, and mirrors m and o back. radiance = true is radiance transport (a
// transmission's BTDF and weight divided by eta'^2, eta' the index seen from the view's side), false
// importance transport.
#pragma once

#include <vector>

#include "ggx_reference.hpp"

namespace ggxref {

// One sample from three uniforms: u1, u2 draw m with `method` (sample()), u3 < F(i.m) reflects,
// else i refracts through m. pdf_m is the method's density of m; pdf_o the density of o with the
// lobe's probability (F or 1 - F); weight = f |o.n| / pdf_o. A sample is invalid (pdf_o = weight = 0,
// m and o as drawn) when i.m <= 0, when a reflection leaves the view's side or a transmission does
// not cross the surface; a transmission's weight is 0 for a view exactly on the horizon. A conductor
// sample without density (the fallback) is returned as is (mirrored back). Method::bounded has no
// dielectric form (its cap leaves out normals whose reflection is lost but whose refraction is not):
// it gives the fallback m = o = n, pdfs and weight 0.
Sample dielectric_sample(Method, const Params&, double eta, bool radiance, double u1, double u2, double u3);

// The density of o that dielectric_sample gives, recomputed from (i, o) alone: F(i.h) pdf_o(o) on
// the view's side, (1 - F(i.m)) pdf_m(m) eta'^2 |o.m| / (i.m + eta' o.m)^2 across (m the generalized
// half vector facing the view's side, i.m > 0 > o.m), 0 on the surface and for bounded.
double dielectric_pdf_o(Method, const Params&, double eta, const Vec3& o);

// The probability of each valid sample's o per bin of the whole sphere, in the layout of
// bin_probabilities (ggx_quadrature.hpp): z = cos theta in [-1, 1] into nz, phi in [0, 2 pi) into
// nphi, index z_bin * nphi + phi_bin; world coordinates for caps_iso. rel_tol: per-panel acceptance.
std::vector<double> dielectric_bin_probabilities(Method, const Params&, double eta, int nz, int nphi);
std::vector<double> dielectric_bin_probabilities(Method, const Params&, double eta, int nz, int nphi, double rel_tol);

// The probability that dielectric_sample returns a valid sample (pdf_o > 0), integrated over the
// microfacet normals (independently of the bins above, which integrate over o). 0 for bounded.
double dielectric_valid_probability(Method, const Params&, double eta);

// The white furnace of the single-scattering dielectric: int dielectric_cos(i, o) do over the view's
// side (reflectance) and over the other side (transmittance), by quadrature over microfacet normals.
// Tangent space when params.n = (0, 0, 1), else isotropic (alpha = ax) about params.n.
struct DielectricAlbedo {
    double reflectance, transmittance;
};
DielectricAlbedo dielectric_albedo(const Params&, double eta, bool radiance);

// The share of the exact dielectric's transmitted energy (importance transport) carried by the normals
// that the bounded cap (Eto & Tokuyoshi) never draws: int over m of VNDF(m) (1 - F(i.m)) weight_t(m)
// where pdf_m(Method::bounded) = 0, over the same integral on all m (bounded_refraction_loss.cpp).
// Tangent space; a view below meets the bounded cap of its mirrored view.
double bounded_lost_transmission(const Params&, double eta);

}  // namespace ggxref
