// histogram_job.cpp - device histogram, expectation, chi-square and files.
#include "histogram_job.hpp"

#include <algorithm>
#include <chrono>
#include <functional>

#include <nlohmann/json.hpp>

#include "atomic_file.hpp"
#include "ggx_stats.hpp"
#include "npy_file.hpp"
#include "plot.hpp"
#include "reference_bridge.hpp"
#include "sample_job.hpp"
#include "report_text.hpp"
#include "theta_check.hpp"
#include "user_fit_checks.hpp"

namespace ggxapp {

namespace {

std::string file_name(const std::string& path)
{
    return path.substr(path.rfind('/') + 1);
}

nlohmann::json summary(const ggxcl::Backend& device, const HistogramJob& job, const ggxcl::Histogram& counts,
                       const ggxref::ChiSquare& fit, double seconds)
{
    nlohmann::json doc = describe_sampling(job.params, job.theta_degrees, job.phi_degrees, job.range);
    doc["expected_from_pdf_of"] = std::string(ggxcl::method_name(job.against));
    doc["direction"] = std::string(ggxcl::field_name(job.direction));
    doc["bins"] = {{"cos_theta", job.bins_z}, {"phi", job.bins_phi}};
    doc["chi_square"] = fit.statistic;
    doc["dof"] = fit.dof;
    doc["p_value"] = fit.p_value;
    doc["bins_used"] = fit.bins_used;
    if (job.params.eta != 0.0f) {
        doc["invalid_samples"] = counts.invalid;
        doc["invalid"] = "samples without density (a reflection that left the view's side, a transmission that did "
                         "not cross), tested as one more category against what the bins leave of 1";
    }
    doc["pooling"] = "bins expecting fewer than 5 samples are pooled into one";
    doc["observed"] = file_name(job.prefix) + ".observed.npy";
    doc["expected"] = file_name(job.prefix) + ".expected.npy";
    doc["device"] = device.device_name();
    doc["api"] = device.api_label();
    doc["device_seconds"] = seconds;
    return doc;
}

// The user sampler's checks, in report order: the chi-square against its own pdf and in rings of
// theta, the integral, the reach, the chi-square against the distribution it claims, the mean
// weight, and its pdfs from (i, o), on one draw of up to 2^20 samples.
std::vector<HistogramCheck> user_sampler_checks(ggxcl::Backend& device, const HistogramJob& job,
                                                const ggxcl::Histogram& counts, const ggxbridge::UserFits& fits)
{
    // The samples judged one by one: the first 2^20 of the range (the pdf checks take 65 536).
    const std::uint64_t drawn_count = std::min<std::uint64_t>(job.range.count, 1u << 20);
    const ggxcl::SampleSet drawn = device.generate(job.params, {job.range.seed, job.range.first, drawn_count},
                                                   judged_fields());
    std::vector<HistogramCheck> checks = {
        chi_square_check("its own pdf", fits.own_fit, job.level, samples_where_zero(counts, fits.own.kept)),
        theta_check(ggxbridge::direction_pdf(device), job.params, drawn, job.direction, job.level), integral_check(fits.own, counts),
        reach_check(fits.own, counts)};
    if (fits.claims) {
        const std::string claim(ggxcl::distribution_name(job.params.user_sampler->distribution()));
        HistogramCheck check = chi_square_check("the claimed " + claim, fits.claimed_fit, job.level,
                                                samples_where_zero(counts, fits.claimed.kept));
        check.numbers["claimed_below_horizon"] = fits.claimed.below;
        check.summary += "; discarded " + readable_number(double(counts.invalid) / double(counts.total())) +
                         " of the samples, the claimed mass below the horizon " + readable_number(fits.claimed.below);
        checks.push_back(check);
    }
    checks.push_back(weight_check(drawn, job.params));
    const std::size_t judged = std::min<std::size_t>(drawn.count, 1 << 16);
    for (HistogramCheck& check : pdf_checks(device, job.params, drawn, judged, fits.claims ? &fits.claimed_method : nullptr))
        checks.push_back(check);
    return checks;
}

} // namespace

std::future<std::vector<double>> start_expectation(const HistogramJob& job)
{
    return std::async(std::launch::async, [job] {
        if (job.params.method == ggxcl::Method::user)  // bins of m: claimed_bins integrates them itself
            return job.direction == ggxcl::Field::o
                       ? ggxbridge::claimed_bin_probabilities(job.params, job.bins_z, job.bins_phi)
                       : std::vector<double>{};
        return ggxbridge::bin_probabilities(job.against, job.params, job.bins_z, job.bins_phi, job.direction);
    });
}

HistogramResult run_histogram_job(ggxcl::Backend& device, const HistogramJob& job,
                                  std::future<std::vector<double>> expectation)
{
    // A small warm-up run (a whole work-group and a tail) builds and
    // JIT-compiles the kernels, so the timing below measures sampling and
    // binning alone.
    device.histogram(job.params, {job.range.seed, job.range.first, device.work_group_size() + 1}, job.bins_z,
                     job.bins_phi, job.direction);
    // The expectation, started before, is awaited first: the timing below
    // then measures the device alone, not the device beside the quadrature.
    const std::vector<double> reference = expectation.get();
    auto start = std::chrono::steady_clock::now();
    ggxcl::Histogram counts = device.histogram(job.params, job.range, job.bins_z, job.bins_phi, job.direction);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool user = job.params.method == ggxcl::Method::user;
    const ggxbridge::BinRequest request{job.bins_z, job.bins_phi, job.direction, job.range.count, &counts.counts};
    const ggxbridge::UserFits fits =
        user ? ggxbridge::user_fits(ggxbridge::direction_pdf(device), job.params, counts, request, reference) : ggxbridge::UserFits{};
    const std::vector<double>& probabilities = user ? fits.own.kept : reference;
    const ggxref::ChiSquare fit =
        user ? fits.own_fit : ggxbridge::histogram_fit(counts, probabilities, job.params.eta != 0.0f);

    std::vector<double> observed(counts.counts.begin(), counts.counts.end()), expected(probabilities.size());
    for (std::size_t b = 0; b < expected.size(); ++b)
        expected[b] = probabilities[b] * double(job.range.count);
    write_npy_f64(job.prefix + ".observed.npy", job.bins_z, job.bins_phi, observed);
    write_npy_f64(job.prefix + ".expected.npy", job.bins_z, job.bins_phi, expected);
    nlohmann::json doc = summary(device, job, counts, fit, seconds);
    HistogramResult result{fit.statistic, fit.p_value, double(job.range.count) / seconds, fit.dof, "", {}};
    if (user) {
        result.checks = user_sampler_checks(device, job, counts, fits);
        doc["expected_from_pdf_of"] = ggxcl::sampler_name(job.params) +
                                      " (its own pdf, integrated adaptively over each bin; the samples it kept)";
        doc["quadrature_error"] = fits.own.error_total();
        doc["discarded_samples"] = counts.invalid;
        doc["discarded"] = "samples whose o is below the horizon with weight 0 (whatever their pdf), tested as one "
                           "more category against what the bins leave of 1";
        for (const HistogramCheck& check : result.checks)
            doc["checks"].push_back({{"name", check.name},
                                     {"summary", check.summary},
                                     {"passed", check.passed},
                                     {"p_value", check.p_value},
                                     {"numbers", check.numbers}});
    }
    write_text_file(job.prefix + ".json", doc.dump(2) + "\n");

    if (job.png) {
        run_plot_script("plot_histogram.py", {job.prefix + ".json", job.prefix + ".png"});
        result.png = job.prefix + ".png";
    }
    return result;
}

HistogramResult run_histogram_job(ggxcl::Backend& device, const HistogramJob& job)
{
    return run_histogram_job(device, job, start_expectation(job));
}

} // namespace ggxapp
