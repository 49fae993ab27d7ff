// user_fit_checks.cpp - a user sampler's histogram, integral, reach and weight checks.
#include "user_fit_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ggx_integrals.hpp"
#include "reference_bridge.hpp"
#include "report_text.hpp"

namespace ggxapp {

namespace {

double discarded_fraction(const ggxcl::Histogram& counts)
{
    const double n = double(counts.total());
    return n > 0.0 ? double(counts.invalid) / n : 0.0;
}

// The binomial standard deviation of the discarded fraction.
double discarded_noise(const ggxcl::Histogram& counts)
{
    const double n = double(std::max<std::uint64_t>(counts.total(), 1)), d = discarded_fraction(counts);
    return std::sqrt(std::max(d * (1.0 - d), 1.0 / n) / n);
}

// A value printed with the digits its error bar resolves (4 at least).
std::string measured(double value, double error)
{
    const int digits = error > 0.0 && std::fabs(value) > 0.0
                           ? std::max(4, int(std::ceil(std::log10(std::fabs(value) / error))) + 1)
                           : 4;
    return readable_number(value, std::min(digits, 9));
}

std::string percent(double fraction) { return readable_number(100.0 * fraction) + " %"; }

} // namespace

std::uint64_t samples_where_zero(const ggxcl::Histogram& counts, const std::vector<double>& kept)
{
    std::uint64_t n = counts.non_finite;
    for (std::size_t b = 0; b < kept.size(); ++b)
        n += kept[b] > 0.0 || std::isnan(kept[b]) ? 0 : counts.counts[b];  // NaN: reported as not finite
    return n;
}

HistogramCheck chi_square_check(const std::string& name, const ggxref::ChiSquare& fit, double level,
                                std::uint64_t where_zero)
{
    HistogramCheck check;
    check.name = name;
    check.p_value = fit.p_value;
    std::ostringstream line;
    line << name << ": chi-square " << fit.statistic << " on " << fit.dof << " dof, p = " << fit.p_value;
    std::string reason;
    if (!std::isfinite(fit.statistic))
        reason = "expected counts not finite: the pdf is NaN or infinite where it was integrated";
    else if (fit.dof <= 0)
        reason = "no degree of freedom: the samples fill one cell at most, so nothing was tested";
    check.passed = reason.empty() && fit.p_value >= level;
    if (!reason.empty())
        line << " (" << reason << ")";
    if (where_zero > 0)
        line << "; " << where_zero << " samples landed in bins where the pdf is 0";
    check.summary = line.str();
    check.numbers = {{"chi_square", fit.statistic}, {"dof", fit.dof}, {"p_value", fit.p_value},
                     {"samples_where_pdf_is_0", where_zero}};
    if (!reason.empty())
        check.numbers["reason"] = reason;
    return check;
}

HistogramCheck integral_check(const ggxbridge::BinIntegrals& own, const ggxcl::Histogram& counts)
{
    const double whole = own.whole_total(), above = own.kept_total(), error = own.error_total();
    const double d = discarded_fraction(counts), noise = discarded_noise(counts);
    const double allowed = 2e-4 + 2.0 * error;
    HistogramCheck check;
    check.name = "pdf integrates to 1";
    const bool to_one = std::fabs(whole - 1.0) <= allowed;
    // An engine's rejection: pdf 0 where it discards, so the pdf integrates to what it keeps.
    const bool to_kept = d > 0.0 && std::fabs(whole - (1.0 - d)) <= allowed + 4.0 * noise;
    const bool resolved = error <= 1e-2;  // beyond: the quadrature did not see the pdf where samples went
    check.passed = std::isfinite(whole) && resolved && (to_one || to_kept);
    std::ostringstream line;
    line << check.name << ": " << measured(whole, error) << " +- " << readable_number(error, 2)
         << " over the sphere (above the horizon " << measured(above, error) << "; discarded " << percent(d)
         << "); allowed: 1 +- " << readable_number(allowed, 2);
    if (d > 0.0)
        line << ", or 1 - discarded = " << measured(1.0 - d, noise) << " +- " << readable_number(allowed + 4.0 * noise, 2)
             << " for a pdf of 0 where it discards";
    if (!std::isfinite(whole))
        line << " (not finite: the pdf is NaN or infinite somewhere)";
    else if (!resolved)
        line << " (unresolved: the quadrature found no density where some samples went, or could not converge; "
                "its error bar is the verdict)";
    else if (to_kept && !to_one)
        line << " (a pdf of 0 where it discards: the density of what it keeps)";
    check.summary = line.str();
    check.numbers = {{"integral", whole},   {"error", error},          {"above_horizon", above},
                     {"discarded", d},      {"discarded_noise", noise}, {"allowed", allowed},
                     {"evaluations", own.evaluations}, {"deepest_halving", own.deepest}};
    return check;
}

HistogramCheck reach_check(const ggxbridge::BinIntegrals& own, const ggxcl::Histogram& counts)
{
    const double n = double(counts.total());
    double unreached = 0.0;
    std::size_t bins = 0;
    for (std::size_t b = 0; b < own.kept.size(); ++b)
        if (n * own.kept[b] >= 20.0 && counts.counts[b] == 0) {
            unreached += own.kept[b];
            ++bins;
        }
    // Below the horizon the pdf holds what the sampler discards there, or nothing (a pdf of 0
    // where it discards).
    const double below = own.whole_total() - own.kept_total(), d = discarded_fraction(counts);
    const double allowed = 1e-3 + 2.0 * own.error_total() + 4.0 * discarded_noise(counts);
    const bool none_below = std::fabs(below) <= 2.0 * own.error_total() + 1e-6;
    const double beyond = none_below ? 0.0 : below - d;
    HistogramCheck check;
    check.name = "pdf where it samples";
    check.passed = std::isfinite(below) && unreached <= 1e-3 && std::fabs(beyond) <= allowed;
    std::ostringstream line;
    line << check.name << ": " << bins << " bins expecting 20 samples or more got none (mass "
         << readable_number(unreached) << "); below the horizon the pdf holds " << readable_number(below)
         << " against " << readable_number(d) << " of the samples discarded there";
    if (!std::isfinite(below))
        line << " (not finite: the pdf is NaN or infinite somewhere)";
    else if (unreached > 1e-3 || beyond > allowed)
        line << "; the pdf is positive where the sampler never goes (mass "
             << readable_number(unreached + std::max(0.0, beyond))
             << " outside its reach): harmless where the pdf is evaluated only at its own samples, wrong where it "
                "weights other strategies' samples (MIS)";
    else if (beyond < -allowed)
        line << "; the sampler sends more samples below the horizon than its pdf puts there";
    check.summary = line.str();
    check.numbers = {{"unreached_bins", bins}, {"unreached_mass", unreached}, {"below_horizon", below},
                     {"discarded", d}, {"beyond_discarded", beyond}};
    return check;
}

HistogramCheck weight_check(const ggxcl::SampleSet& samples, const ggxcl::SampleParams& params)
{
    ggxcl::FurnaceSums sums;
    sums.count = samples.count;
    for (float w : samples.weight) {
        sums.sum += double(w);
        sums.sum_of_squares += double(w) * double(w);
    }
    const ggxref::Params ref = ggxbridge::reference_params(ggxcl::normalized(params));
    const double albedo = ref.i.z > 0.0 ? ggxref::reflected_radiance(ref, ggxref::Light{}) : 0.0;
    const double mean = sums.mean(), noise = std::sqrt(std::max(sums.variance(), 0.0) / double(sums.count));
    const double allowed = 5.0 * noise + 1e-4 * albedo + 1e-7;
    HistogramCheck check;
    check.name = "mean weight is the albedo";
    check.passed = std::isfinite(mean) && std::fabs(mean - albedo) <= allowed;
    std::ostringstream line;
    line << check.name << ": " << measured(mean, noise) << " +- " << readable_number(noise, 2) << " over "
         << sums.count << " samples against the BRDF's albedo " << readable_number(albedo, 6);
    if (albedo > 0.0)
        line << " (ratio " << readable_number(mean / albedo, 5) << ")";
    if (!check.passed)
        line << "; the weights do not belong to these samples: their mean is "
             << (albedo > 0.0 ? readable_number(mean / albedo, 4) + " times" : "not") << " the albedo";
    check.summary = line.str();
    check.numbers = {{"mean_weight", mean}, {"noise", noise}, {"albedo", albedo}, {"allowed", allowed}};
    return check;
}

} // namespace ggxapp
