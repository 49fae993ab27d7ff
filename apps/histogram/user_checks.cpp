// user_checks.cpp - a user sampler's pdf_o judged sample by sample against recomputed pdfs.
#include "user_checks.hpp"

#include "reference_bridge.hpp"
#include "report_text.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ggxapp {

namespace {

constexpr double agreement = 1e-3;      // a ratio within 1 +- this agrees
constexpr double cancellation = 0.01;   // |i.h| below this: h = normalize(i + o) is ill-conditioned

double quantile(const std::vector<double>& sorted, double q)
{
    if (sorted.empty())
        return 0.0;
    return sorted[std::min(sorted.size() - 1, std::size_t(q * double(sorted.size() - 1) + 0.5))];
}

// |i.h| with h = normalize(i + o), in double.
double half_vector_cosine(const ggxcl::Vec3& i, const ggxcl::Vec3& o)
{
    const double h[3] = {double(i.x) + o.x, double(i.y) + o.y, double(i.z) + o.z};
    const double len = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    return len > 0.0 ? std::fabs(h[0] * i.x + h[1] * i.y + h[2] * i.z) / len : 0.0;
}

PdfAgreement pdf_agreement(const ggxcl::SampleSet& samples, std::size_t count, const ggxcl::Vec3& view,
                           const std::vector<float>& recomputed)
{
    PdfAgreement a;
    a.samples = count;
    std::vector<double> ratios;
    for (std::size_t j = 0; j < count; ++j) {
        const ggxcl::Vec3 o = samples.o_at(j), m = samples.m_at(j);
        const double m2 = double(m.x) * m.x + double(m.y) * m.y + double(m.z) * m.z;
        a.not_unit_m += !(std::fabs(m2 - 1.0) <= 2e-5);
        const float returned = samples.pdf_o[j], again = recomputed[j];
        if (o.z <= 0.0f && samples.weight[j] == 0.0f) {
            ++a.discarded;
        } else if (!std::isfinite(returned)) {
            ++a.not_finite;
        } else if (!(returned > 0.0f)) {
            ++a.not_positive;
        } else if (half_vector_cosine(view, o) < cancellation) {
            ++a.ill_conditioned;
        } else {
            ++a.with_density;
            const double ratio = again > 0.0f && std::isfinite(again) ? double(returned) / double(again) : INFINITY;
            ratios.push_back(ratio);
            a.above += ratio > 1.0 + agreement;
            a.below += ratio < 1.0 - agreement;
        }
    }
    a.disagree = a.above + a.below;
    std::sort(ratios.begin(), ratios.end());
    a.median = quantile(ratios, 0.5);
    a.low = quantile(ratios, 0.001);
    a.high = quantile(ratios, 0.999);
    return a;
}

// "a factor X (= 1/G1(i), ...)": the constant factor's name where it matches one of this view.
std::string factor_name(double factor, const ggxcl::SampleParams& params)
{
    const ggxref::Params ref = ggxbridge::reference_params(ggxcl::normalized(params));
    const double g1 = ggxref::G1(ref.i, ref.ax, ref.ay);
    const std::pair<double, const char*> known[] = {{1.0 / g1, "1/G1(i), the view's masking divided out"},
                                                    {g1, "G1(i), the view's masking applied twice"},
                                                    {2.0, "2"},
                                                    {0.5, "1/2"},
                                                    {4.0, "4"},
                                                    {0.25, "1/4"}};
    std::string out = "a factor " + readable_number(factor, 4);
    for (const auto& [value, name] : known)
        if (g1 > 0.0 && std::fabs(factor / value - 1.0) <= 2.0 * agreement)
            return out + " (= " + name + ")";
    return out;
}

// The diagnosis of the ratios: the right shape with another normalization, or another shape.
std::string ratio_diagnosis(const PdfAgreement& a, const ggxcl::SampleParams& params)
{
    if (a.with_density == 0 || a.disagree == 0)
        return "";
    if (std::isfinite(a.high) && a.low > 0.0 && a.high / a.low - 1.0 < agreement)
        return "; the right shape with another normalization: " + factor_name(a.median, params);
    return "; the shape differs: the ratio runs from " + readable_number(a.low, 4) + " to " + readable_number(a.high, 4) +
           " (0.1 and 99.9 percentiles), median " + readable_number(a.median, 4);
}

std::string count_of(std::size_t n, std::size_t of) { return std::to_string(n) + " of " + std::to_string(of); }

HistogramCheck agreement_check(const std::string& name, const PdfAgreement& a, const ggxcl::SampleParams& params)
{
    HistogramCheck check;
    check.name = name;
    check.passed = a.with_density > 0 && a.not_finite == 0 && a.not_positive == 0 &&
                   double(a.disagree) <= 1e-3 * double(a.with_density);
    std::ostringstream line;
    line << name << ": " << count_of(a.disagree, a.with_density) << " judged samples differ by more than 1e-3 ("
         << a.above << " above, " << a.below << " below; returned / recomputed: median " << readable_number(a.median, 5)
         << ", 0.1-99.9 % " << readable_number(a.low, 5) << " to " << readable_number(a.high, 5) << ")";
    if (a.not_finite)
        line << "; " << a.not_finite << " kept samples have a pdf that is NaN or infinite";
    if (a.not_positive)
        line << "; " << a.not_positive << " kept samples (o above the horizon, or a weight) have pdf <= 0";
    if (a.with_density == 0)
        line << "; no sample could be judged";
    line << "; set apart: " << a.discarded << " discarded (o below the horizon, weight 0), " << a.ill_conditioned
         << " ill-conditioned (|i.h| < " << cancellation << ")";
    if (a.not_unit_m)
        line << "; " << a.not_unit_m << " normals m not of unit length";
    line << ratio_diagnosis(a, params);
    check.summary = line.str();
    check.numbers = {{"samples", a.samples},         {"discarded", a.discarded},
                     {"not_finite", a.not_finite},   {"not_positive", a.not_positive},
                     {"ill_conditioned", a.ill_conditioned}, {"judged", a.with_density},
                     {"disagree", a.disagree},       {"above", a.above},
                     {"below", a.below},             {"ratio_median", a.median},
                     {"ratio_p001", a.low},          {"ratio_p999", a.high},
                     {"not_unit_m", a.not_unit_m}};
    return check;
}

} // namespace

std::vector<PdfAgreement> pdf_agreements(ggxcl::Backend& device, const ggxcl::SampleParams& params,
                                         const ggxcl::SampleSet& samples, std::size_t count,
                                         const ggxcl::Method* claimed)
{
    std::vector<ggxcl::Vec3> directions(count);
    for (std::size_t j = 0; j < count; ++j)
        directions[j] = samples.o_at(j);
    const ggxcl::Vec3 view = ggxcl::normalized(params).view;
    std::vector<PdfAgreement> out = {pdf_agreement(samples, count, view, device.pdf(params, directions))};
    if (claimed) {
        ggxcl::SampleParams theirs = params;
        theirs.method = *claimed;
        theirs.user_sampler = nullptr;
        out.push_back(pdf_agreement(samples, count, view, device.pdf(theirs, directions)));
    }
    return out;
}

std::vector<PdfAgreement> pdf_agreements(ggxcl::Backend& device, const ggxcl::SampleParams& params,
                                         const ggxcl::SampleRange& range, const ggxcl::Method* claimed)
{
    const ggxcl::SampleSet samples = device.generate(params, range, judged_fields());
    return pdf_agreements(device, params, samples, samples.count, claimed);
}

std::vector<HistogramCheck> pdf_checks(ggxcl::Backend& device, const ggxcl::SampleParams& params,
                                       const ggxcl::SampleSet& samples, std::size_t count,
                                       const ggxcl::Method* claimed)
{
    const std::vector<PdfAgreement> agreements = pdf_agreements(device, params, samples, count, claimed);
    std::vector<HistogramCheck> checks = {agreement_check("pdf from (i, o)", agreements[0], params)};
    if (claimed) {
        const std::string claim(ggxcl::distribution_name(ggxcl::method_traits(*claimed).normals));
        checks.push_back(agreement_check("pdf of the claimed " + claim, agreements[1], params));
    }
    return checks;
}

} // namespace ggxapp
