// user_checks.cpp - the bins under a device pdf, and the pdf checks of a user sampler.
#include "user_checks.hpp"

#include "report_text.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ggxapp {

namespace {

// The relative difference of a and b (0 when both are 0).
double relative_difference(double a, double b)
{
    const double scale = std::max(std::fabs(a), std::fabs(b));
    return scale > 0.0 ? std::fabs(a - b) / scale : 0.0;
}

} // namespace

HistogramCheck pdf_integral_check(const std::vector<double>& probabilities, double quadrature_error)
{
    double total = 0.0;
    for (double p : probabilities)
        total += p;
    const double allowed = 1e-3 + 10.0 * quadrature_error;
    HistogramCheck check;
    check.name = "pdf integrates to 1";
    check.passed = std::fabs(total - 1.0) <= allowed;
    check.summary = check.name + ": " + readable_number(total) + " over the sphere (allowed: 1 +- " +
                    readable_number(allowed) + ")";
    return check;
}

PdfAgreement pdf_agreement(const std::vector<float>& sampled, const std::vector<float>& recomputed)
{
    PdfAgreement a;
    for (std::size_t j = 0; j < sampled.size(); ++j) {
        if (!(sampled[j] > 0.0f))
            continue;
        ++a.with_density;
        const double d = relative_difference(sampled[j], recomputed[j]);
        a.worst = std::max(a.worst, std::isfinite(d) ? d : 1.0);
        a.disagree += !(d <= 1e-3);
    }
    return a;
}

std::vector<PdfAgreement> pdf_agreements(const PdfDevice& device, const ggxcl::SampleParams& params,
                                         const ggxcl::SampleRange& range, const ggxcl::Method* claimed)
{
    const ggxcl::SampleSet samples = device.generate(params, range, {ggxcl::Field::o, ggxcl::Field::pdf_o});
    std::vector<ggxcl::Vec3> directions(range.count);
    for (std::size_t j = 0; j < directions.size(); ++j)
        directions[j] = samples.o_at(j);
    std::vector<PdfAgreement> out = {pdf_agreement(samples.pdf_o, device.pdf(params, directions))};
    if (claimed) {
        ggxcl::SampleParams theirs = params;
        theirs.method = *claimed;
        theirs.user_sampler = nullptr;
        out.push_back(pdf_agreement(samples.pdf_o, device.pdf(theirs, directions)));
    }
    return out;
}

std::vector<HistogramCheck> pdf_checks(const PdfDevice& device, const ggxcl::SampleParams& params,
                                       const ggxcl::SampleRange& range, const ggxcl::Method* claimed)
{
    const std::vector<PdfAgreement> agreements = pdf_agreements(device, params, range, claimed);
    std::vector<HistogramCheck> checks;
    for (std::size_t k = 0; k < agreements.size(); ++k) {
        const PdfAgreement& a = agreements[k];
        HistogramCheck check;
        const std::string_view claim = ggxcl::distribution_name(ggxcl::method_traits(*claimed).normals);
        check.name = k == 0 ? "pdf from (i, o)" : "pdf of the claimed " + std::string(claim);
        check.passed = a.with_density > 0 && double(a.disagree) <= 1e-3 * double(a.with_density);
        check.summary = check.name + ": " + std::to_string(a.disagree) + " of " + std::to_string(a.with_density) +
                        " samples with a density differ by more than 1e-3 (relative), the largest by " +
                        readable_number(a.worst);
        checks.push_back(check);
    }
    return checks;
}

} // namespace ggxapp
