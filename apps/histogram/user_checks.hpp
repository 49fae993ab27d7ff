// user_checks.hpp - what `ggx histogram --sampler` tests of a user sampler
// beyond the chi-square against its own pdf: the bins' probabilities under
// that pdf (the user's device function, integrated on the host by Gauss-
// Legendre rules over each bin), the chi-square against the distribution the
// file claims (the reference's GGX VNDF or NDF), and its pdf_o against the
// pdf recomputed from (i, o) by its own function and, where it claims one,
// by the claimed distribution's.
#pragma once

#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace ggxapp {

// One check's verdict, for the report and --check.
struct HistogramCheck {
    std::string name;      // "own pdf", "claimed vndf", "pdf from (i, o)", ...
    std::string summary;   // one line for people
    double p_value = -1;   // chi-square checks; -1 otherwise
    bool passed = true;    // p >= level for chi-square checks (level: --check, else 1e-3)
};

// Each bin's probability under params' pdf (Sampler::pdf, over the whole sphere) by the
// 16x16-point rule, with the change from the 8x8-point rule's, |fine - coarse| summed over the
// bins, in `quadrature_error`.
std::vector<double> pdf_bin_probabilities(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params, int bins_z,
                                          int bins_phi, double& quadrature_error);

// The pdf's integral over the sphere (the bins' sum) must be 1: within 1e-3 plus ten times the
// quadrature error (a chi-square, which normalizes the expected counts, cannot
// tell a pdf off by a constant factor).
HistogramCheck pdf_integral_check(const std::vector<double>& probabilities, double quadrature_error);

// The built-in method whose pdf is the claimed distribution's (heitz for vndf, ndf for ndf); false
// for a density of its own.
bool claimed_method(ggxcl::Distribution distribution, ggxcl::Method& method);

// pdf_o of `count` samples against the pdf recomputed from (i, o) by the sampler and, with
// `claimed`, by that method: a sample disagrees where the relative difference exceeds 1e-3;
// the check fails when more than 0.1 % of the samples with a density disagree.
std::vector<HistogramCheck> pdf_checks(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params,
                                       const ggxcl::SampleRange& range, const ggxcl::Method* claimed);

} // namespace ggxapp
