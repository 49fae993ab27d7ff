// user_checks.hpp - what `ggx histogram --sampler` tests of a user sampler's
// samples one by one: its pdf_o against the pdf recomputed from (i, o) by
// its own function and, where it claims one, by the claimed distribution's,
// each sample judged by one precedence (docs/USER-SAMPLERS.md "How each
// sample is judged"), with the ratio's spread and a diagnosis.  The checks
// on the histogram are user_fit_checks.hpp's.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <ggxcl/ggxcl.hpp>

#include "pdf_bins.hpp"

namespace ggxapp {

// One check's verdict, for the report and --check.
struct HistogramCheck {
    std::string name;      // "its own pdf", "pdf integrates to 1", "pdf from (i, o)", ...
    std::string summary;   // what was found, for people: by how much and which way
    double p_value = -1;   // chi-square checks; -1 otherwise
    bool passed = true;    // p >= level for chi-square checks (level: --check, else 1e-3)
    nlohmann::json numbers = nlohmann::json::object();  // the measured values, for the JSON
};

// How a sampler's pdf_o agrees with a pdf recomputed from (i, o), sample by sample, in this order:
// a sample whose o is below the horizon with weight 0 is discarded (whatever its pdf); a returned
// pdf that is NaN or infinite fails; a returned pdf <= 0 fails (its sample was kept); where the
// half vector i + o nearly cancels (|i.h| < 0.01) the recomputation is ill-conditioned and the
// sample is set apart; otherwise the ratio returned / recomputed is judged (within 1e-3 of 1, or a
// disagreement; a recomputed pdf <= 0, NaN or infinite disagrees).
struct PdfAgreement {
    std::size_t samples = 0, discarded = 0, not_finite = 0, not_positive = 0, ill_conditioned = 0;
    std::size_t with_density = 0;  // judged by their ratio
    std::size_t disagree = 0;      // of those, off by more than 1e-3 (or recomputed without a density)
    std::size_t above = 0, below = 0;  // ratio > 1 + 1e-3, < 1 - 1e-3
    std::size_t not_unit_m = 0;        // samples whose m is off unit length by more than 1e-5 (relative)
    double median = 0, low = 0, high = 0;  // the ratio's median, 0.1 and 99.9 percentiles
    // Samples that fail: not finite, not positive, disagreeing.
    std::size_t failures() const { return not_finite + not_positive + disagree; }
};

// The fields the checks read of each sample: one program draws them for all.
inline ggxcl::FieldSet judged_fields()
{
    return {ggxcl::Field::m, ggxcl::Field::o, ggxcl::Field::pdf_o, ggxcl::Field::weight};
}

// The first `count` of `samples` (judged_fields) against the pdf recomputed by params' sampler
// and, with `claimed`, by that method's (in that order).
std::vector<PdfAgreement> pdf_agreements(ggxcl::Backend& device, const ggxcl::SampleParams& params,
                                         const ggxcl::SampleSet& samples, std::size_t count,
                                         const ggxcl::Method* claimed);
// The same for the samples of `range`, drawn here.
std::vector<PdfAgreement> pdf_agreements(ggxcl::Backend& device, const ggxcl::SampleParams& params,
                                         const ggxcl::SampleRange& range, const ggxcl::Method* claimed);

// pdf_o of the first `count` of `samples` against the pdf recomputed from (i, o) by the sampler
// and, with `claimed`, by that method: a check fails when a sample's pdf is not finite or not
// positive where it was kept, when more than 0.1 % of the judged samples disagree, or when none
// is judged.
std::vector<HistogramCheck> pdf_checks(ggxcl::Backend& device, const ggxcl::SampleParams& params,
                                       const ggxcl::SampleSet& samples, std::size_t count,
                                       const ggxcl::Method* claimed);

} // namespace ggxapp
