// user_checks.hpp - what `ggx histogram --sampler` tests of a user sampler
// beyond the chi-square against its own pdf (bridge/pdf_bins.hpp): the pdf's
// integral, the chi-square against the distribution the file claims (the
// reference's GGX VNDF or NDF), and its pdf_o against the pdf recomputed
// from (i, o) by its own function and, where it claims one, by the claimed
// distribution's.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "pdf_bins.hpp"

namespace ggxapp {

// One check's verdict, for the report and --check.
struct HistogramCheck {
    std::string name;      // "own pdf", "claimed vndf", "pdf from (i, o)", ...
    std::string summary;   // one line for people
    double p_value = -1;   // chi-square checks; -1 otherwise
    bool passed = true;    // p >= level for chi-square checks (level: --check, else 1e-3)
};

// The pdf's integral over the sphere (the bins' sum) must be 1: within 1e-3 plus ten times the
// quadrature error (a chi-square, which normalizes the expected counts, cannot
// tell a pdf off by a constant factor).
HistogramCheck pdf_integral_check(const std::vector<double>& probabilities, double quadrature_error);

// How a sampler's pdf_o agrees with a pdf recomputed from (i, o): of the samples with a density
// (pdf_o > 0), how many differ by more than 1e-3 (relative), and the largest difference.
struct PdfAgreement {
    std::size_t with_density = 0, disagree = 0;
    double worst = 0.0;
};

// Where the samples and their recomputed pdf come from: a Sampler or a VulkanSampler.
struct PdfDevice {
    std::function<ggxcl::SampleSet(const ggxcl::SampleParams&, const ggxcl::SampleRange&, ggxcl::FieldSet)> generate;
    ggxbridge::DirectionPdf pdf;
};

template <class Api>
PdfDevice pdf_device(Api& sampler)
{
    return {[&sampler](const ggxcl::SampleParams& p, const ggxcl::SampleRange& r, ggxcl::FieldSet f) {
                return sampler.generate(p, r, f);
            },
            ggxbridge::direction_pdf(sampler)};
}

// The samples of `range` against the pdf recomputed by params' sampler and, with `claimed`, by
// that method's (in that order).
std::vector<PdfAgreement> pdf_agreements(const PdfDevice& device, const ggxcl::SampleParams& params,
                                         const ggxcl::SampleRange& range, const ggxcl::Method* claimed);

// pdf_o of `count` samples against the pdf recomputed from (i, o) by the sampler and, with
// `claimed`, by that method: a sample disagrees where the relative difference exceeds 1e-3;
// the check fails when more than 0.1 % of the samples with a density disagree.
std::vector<HistogramCheck> pdf_checks(const PdfDevice& device, const ggxcl::SampleParams& params,
                                       const ggxcl::SampleRange& range, const ggxcl::Method* claimed);

} // namespace ggxapp
