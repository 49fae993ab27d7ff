// bench_report.cpp - CSV and Markdown of `ggx bench`: per device the answer
// (which sampler is fastest, most accurate, best at equal time) first, then
// every table and, with --eta, the rough dielectric's section; with two
// devices their rows side by side; the process rows last.
#include "bench_report.hpp"

#include "report_text.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <thread>

namespace ggxapp {

namespace {

// The rows' method names: the library's methods in their order (ggxcl::all_methods), then the
// user samplers' in the order of their rows.
std::vector<std::string> method_order(const BenchReport& r)
{
    std::vector<std::string> out;
    for (ggxcl::Method m : ggxcl::all_methods)
        out.emplace_back(ggxcl::method_name(m));
    for (const BenchRow& row : r.rows)
        if (row.method != "all" && std::find(out.begin(), out.end(), row.method) == out.end())
            out.push_back(row.method);
    return out;
}
const char* const device_modes[] = {"precise", "relaxed"};

std::string ns_cell(const BenchRow* row)
{
    if (!row)
        return "–";
    return timing_text(row->timing, 2);
}

// Millions of samples per second, as people read them ("263").
std::string msps(const BenchRow* row)
{
    return readable_number(1e3 / row->timing.median);
}

// The default mode's row of (method, job): what a user runs.
const BenchRow* default_row(const BenchReport& r, const std::string& method, const std::string& job)
{
    return find_row(r, method, "precise", job);
}

double ratio(const BenchRow* slow, const BenchRow* fast)
{
    return slow->timing.median / fast->timing.median;
}

// The best of one column: the sampler with the lowest value.
struct Best {
    std::string who;
    double value = 0;
    bool found = false;
    void offer(const std::string& name, double v)
    {
        if (!found || v < value)
            who = name, value = v, found = true;
    }
};

struct Answer {
    Best fastest, fastest_fused, accurate, equal_time, equal_time_sobol;
};

Answer best_samplers(const BenchReport& r)
{
    Answer a;
    for (const std::string& m : method_order(r)) {
        const BenchRow* w = default_row(r, m, "write");
        const BenchRow* f = default_row(r, m, "furnace");
        const BenchRow* sobol = find_row(r, m, "precise", "furnace", "sobol");
        if (w)
            a.fastest.offer(m, w->timing.median);
        if (f)
            a.fastest_fused.offer(m, f->timing.median);
        if (w && w->has_error)
            a.accurate.offer(m, w->error.angle_p99);
        if (f && f->variance > 0)
            a.equal_time.offer(m, rmse_at_budget(*f, r));
        if (sobol && sobol->rmse_measured > 0)
            a.equal_time_sobol.offer(m, sobol->rmse_measured);
    }
    return a;
}

std::string bold_if(const std::string& text, bool best)
{
    return best ? "**" + text + "**" : text;
}

// Per sampler, the answer's three numbers; the best of each in bold.
void write_answer_table(std::ostream& md, const BenchReport& r, const Answer& a)
{
    md << "| sampler | writing m + pdf_m | fused estimator | angle error, 99th percentile | RMSE at equal time |\n"
          "|---|---|---|---|---|\n";
    for (const std::string& m : method_order(r)) {
        const BenchRow* w = default_row(r, m, "write");
        const BenchRow* f = default_row(r, m, "furnace");
        if (!w && !f)
            continue;
        md << "| " << m << " | "
           << (w ? bold_if(rate_text(1e9 / w->timing.median, "samples/s"), a.fastest.who == m) : "–") << " | "
           << (f ? bold_if(rate_text(1e9 / f->timing.median, "samples/s"), a.fastest_fused.who == m) : "–") << " | "
           << (w && w->has_error ? bold_if(readable_number(w->error.angle_p99) + " rad", a.accurate.who == m) : "–")
           << " | "
           << (f && f->variance > 0 ? bold_if(readable_number(rmse_at_budget(*f, r)), a.equal_time.who == m) : "–")
           << " |\n";
    }
}

// What a user asks first: which sampler is fastest here, which most accurate, which gives the lowest
// error at equal time; in the default mode (precise) with independent uniforms.
void write_answer(std::ostream& md, const BenchReport& r)
{
    const Answer a = best_samplers(r);
    md << "## Which sampler on this device\n\n";
    if (a.fastest.found)
        md << "- **Fastest**: " << a.fastest.who << ", " << rate_text(1e9 / a.fastest.value, "samples/s")
           << " writing m and pdf_m (" << duration_text(a.fastest.value) << " a sample)"
           << (a.fastest_fused.found ? "; in a fused estimator (the white furnace, nothing written): " +
                                           a.fastest_fused.who + ", " +
                                           rate_text(1e9 / a.fastest_fused.value, "samples/s")
                                     : "")
           << ".\n";
    if (a.accurate.found)
        md << "- **Most accurate**: " << a.accurate.who << ": 99 % of its directions within "
           << readable_number(a.accurate.value) << " rad of the double-precision reference's on the same uniforms.\n";
    else
        md << "- **Most accurate**: not measured in this run (--no-accuracy).\n";
    if (a.equal_time.found) {
        md << "- **Lowest error at equal time**: " << a.equal_time.who << ", RMSE " << readable_number(a.equal_time.value)
           << " per cell when the " << r.scene_size << " x " << r.scene_size << " albedo table gets "
           << readable_number(r.budget_ms) << " ms (its variance per sample and its fused speed together)";
        if (a.equal_time_sobol.found)
            md << "; with Sobol points instead of independent uniforms: " << a.equal_time_sobol.who << ", RMSE "
               << readable_number(a.equal_time_sobol.value) << " (measured)";
        md << ".\n";
    }
    md << "\nPrecise mode (the default), independent uniforms (Philox); the sections below give every mode, job "
          "and sequence.\n\n";
    write_answer_table(md, r, a);
    md << "\n";
}


void write_speed_table(std::ostream& md, const BenchReport& r)
{
    md << "| method | precision | write m + pdf_m: ns | M samples/s | fused furnace: ns | world space o: ns | "
          "per-sample view, alpha: ns |\n|---|---|---|---|---|---|---|\n";
    for (const std::string& m : method_order(r))
        for (const char* mode : {"precise", "precise-unguarded", "relaxed", "native"}) {
            const BenchRow* w = find_row(r, m, mode, "write");
            if (!w)
                continue;
            md << "| " << m << " | " << mode << " | " << ns_cell(w) << " | " << msps(w) << " | "
               << ns_cell(find_row(r, m, mode, "furnace")) << " | " << ns_cell(find_row(r, m, mode, "world")) << " | "
               << ns_cell(find_row(r, m, mode, "per-sample")) << " |\n";
        }
    if (r.has_vectorized)
        md << "| caps | native, vectorized (omp simd) | – | – | " << timing_text(r.vectorized, 2) << " | – | – |\n";
    if (const BenchRow* store = find_row(r, "all", "store-only", "write"))
        md << "| (none) | store only: the write job's bytes | " << ns_cell(store) << " | " << msps(store)
           << " | – | – | – |\n";
}

void write_accuracy_tables(std::ostream& md, const BenchReport& r)
{
    md << "| method | precision | angle p99 (rad) | angle max | pdf rel. p99 | pdf rel. max |\n|---|---|---|---|---|---|\n";
    for (const std::string& m : method_order(r))
        for (const char* mode : {"precise", "relaxed", "native"}) {
            const BenchRow* w = find_row(r, m, mode, "write");
            if (w && w->has_error)
                md << "| " << m << " | " << mode << " | " << readable_number(w->error.angle_p99) << " | " << readable_number(w->error.angle_max)
                   << " | " << readable_number(w->error.pdf_p99) << " | " << readable_number(w->error.pdf_max) << " |\n";
        }
}

void write_variance_table(std::ostream& md, const BenchReport& r)
{
    md << "| method | precision | variance per sample | mean albedo | fused ns | efficiency 1/(var s) | RMSE in "
       << fixed(r.budget_ms, 1) << " ms |\n|---|---|---|---|---|---|---|\n";
    for (const std::string& m : method_order(r))
        for (const char* mode : device_modes) {
            const BenchRow* f = find_row(r, m, mode, "furnace");
            if (f && f->variance > 0)
                md << "| " << m << " | " << mode << " | " << fixed(f->variance, 5) << " | " << fixed(f->mean_albedo, 5) << " | "
                   << fixed(f->timing.median, 2) << " | " << readable_number(efficiency(*f)) << " | " << readable_number(rmse_at_budget(*f, r))
                   << " |\n";
        }
}

// Precise mode with each sequence: speed, numerical error and the albedo
// table's RMSE at the budget, measured (the model's RMSE assumes independent
// uniforms).
void write_sequence_table(std::ostream& md, const BenchReport& r)
{
    md << "| method | sequence | write ns | fused ns | angle p99 (rad) | samples per cell | RMSE in "
       << fixed(r.budget_ms, 1) << " ms, measured |\n|---|---|---|---|---|---|---|\n";
    for (const std::string& m : method_order(r))
        for (const char* sequence : {"philox", "sobol"}) {
            const BenchRow* w = find_row(r, m, "precise", "write", sequence);
            const BenchRow* f = find_row(r, m, "precise", "furnace", sequence);
            if (!f || f->rmse_measured == 0)
                continue;
            md << "| " << m << " | " << sequence << " | " << ns_cell(w) << " | " << ns_cell(f) << " | "
               << (w && w->has_error ? readable_number(w->error.angle_p99) : "–") << " | " << samples_at_budget(*f, r) << " | "
               << readable_number(f->rmse_measured) << " |\n";
        }
}

// The CSV's last columns: the row's eta (0: a conductor), and a dielectric's transport and
// furnace accuracy (R, T, the reference's and their standard errors).
const char* const dielectric_csv_header =
    ",eta,transport,reflectance,reflectance_exact,reflectance_se,transmittance,transmittance_exact,transmittance_se";

std::string dielectric_csv_cells(const BenchRow& row)
{
    std::ostringstream cells;
    cells << std::setprecision(6) << "," << row.eta << "," << row.transport;
    const DielectricAccuracy& a = row.dielectric;
    if (a.measured)
        cells << "," << a.reflectance << "," << a.exact_reflectance << "," << a.reflectance_se << ","
              << a.transmittance << "," << a.exact_transmittance << "," << a.transmittance_se;
    else
        cells << ",,,,,,";
    return cells.str();
}

std::string signed_fixed(double value, int digits)
{
    return (value >= 0 ? "+" : "") + fixed(value, digits);
}

// The dielectric beside the conductor, per method, precision and job: both times and the ratio.
void write_dielectric_speed(std::ostream& md, const BenchReport& r)
{
    md << "| method | precision | job | conductor: ns | dielectric: ns | dielectric: M samples/s | dielectric / "
          "conductor |\n|---|---|---|---|---|---|---|\n";
    for (const std::string& m : method_order(r))
        for (const char* mode : device_modes)
            for (const char* job : {"write-o", "furnace"}) {
                const BenchRow* conductor = find_row(r, m, mode, job);
                const BenchRow* dielectric = find_row(r, m, mode, job, "philox", true);
                if (!conductor || !dielectric)
                    continue;
                const bool furnace = std::string(job) == "furnace";
                md << "| " << m << " | " << mode << " | " << (furnace ? "fused furnace" : "write o + pdf_o") << " | "
                   << ns_cell(conductor) << " | " << ns_cell(dielectric) << " | "
                   << fixed(1e3 / dielectric->timing.median, 1) << " | " << fixed(ratio(dielectric, conductor), 2)
                   << "x |\n";
            }
}

// The dielectric furnace's reflectance and transmittance against the reference, in standard errors.
void write_dielectric_accuracy(std::ostream& md, const BenchReport& r)
{
    const DielectricAccuracy* first = nullptr;
    for (const BenchRow& row : r.rows)
        if (row.dielectric.measured && !first)
            first = &row.dielectric;
    if (!first)
        return;
    md << "\nThe fused furnace's reflectance R and transmittance T against the reference's quadrature over "
          "normals (ggxref::dielectric_albedo: R = "
       << fixed(first->exact_reflectance, 5) << ", T = " << fixed(first->exact_transmittance, 5) << "), "
       << first->samples << " samples in " << dielectric_streams
       << " independent streams; the error in standard errors of the mean, from the streams' spread.\n\n"
       << "| method | precision | R | error (SE) | T | error (SE) |\n|---|---|---|---|---|---|\n";
    for (const std::string& m : method_order(r))
        for (const char* mode : device_modes)
            if (const BenchRow* f = find_row(r, m, mode, "furnace", "philox", true); f && f->dielectric.measured)
                md << "| " << m << " | " << mode << " | " << fixed(f->dielectric.reflectance, 5) << " | "
                   << signed_fixed(f->dielectric.reflectance_z(), 1) << " | " << fixed(f->dielectric.transmittance, 5)
                   << " | " << signed_fixed(f->dielectric.transmittance_z(), 1) << " |\n";
}

void write_dielectric_section(std::ostream& md, const BenchReport& r)
{
    md << "\n## Rough dielectric: eta " << r.eta << ", " << r.transport << " transport\n\n"
       << "Each method with SampleParams::eta = " << r.eta
       << " (each sample reflects with the exact Fresnel F(i.m), else refracts: a third uniform) beside the same "
          "method as a conductor (Fresnel 1), timed in the same interleaved rounds. The write job here stores o + "
          "pdf_o (the direction drawn and its density over the whole sphere; with m + pdf_m alone the lobe choice "
          "would be left out), for the conductor too; the fused furnace sums the weights and, apart, the "
          "reflected ones. The ratio is what the third uniform and the refraction cost.\n\n";
    write_dielectric_speed(md, r);
    for (const ggxcl::MethodTraits& t : ggxcl::method_table)
        if (!t.dielectric && std::any_of(r.rows.begin(), r.rows.end(),
                                         [&](const BenchRow& row) { return row.method == t.name; }))
            md << "\n" << t.name << ": no dielectric rows; it has no exact dielectric sampler (" << t.limits << ").\n";
    write_dielectric_accuracy(md, r);
}

} // namespace

const BenchRow* find_row(const BenchReport& r, const std::string& method, const std::string& precision,
                         const std::string& job, const std::string& sequence, bool dielectric)
{
    for (const BenchRow& row : r.rows)
        if (row.method == method && row.precision == precision && row.job == job && row.sequence == sequence &&
            (row.eta != 0.0f) == dielectric)
            return &row;
    return nullptr;
}

BenchRow row_of(const std::string& method, const std::string& precision, const std::string& job, Timing timing)
{
    BenchRow row;
    row.method = method;
    row.precision = precision;
    row.job = job;
    row.timing = timing;
    return row;
}

std::uint64_t samples_at_budget(const BenchRow& row, const BenchReport& report)
{
    double cells = double(report.scene_size) * report.scene_size;
    return std::max<std::uint64_t>(1, std::uint64_t(report.budget_ms * 1e6 / (cells * row.timing.median)));
}

double efficiency(const BenchRow& row)
{
    return row.variance > 0 ? 1.0 / (row.variance * row.timing.median * 1e-9) : 0.0;
}

double rmse_at_budget(const BenchRow& row, const BenchReport& report)
{
    double cells = double(report.scene_size) * report.scene_size;
    double samples_per_cell = report.budget_ms * 1e6 / (cells * row.timing.median);
    return row.variance > 0 ? std::sqrt(row.variance / samples_per_cell) : 0.0;
}

std::string machine_description()
{
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " logical cores";
}

namespace {

struct CsvRow {
    BenchRow row;
    std::uint64_t samples_per_run;
};

// Start-up, the commands and small enqueues as rows: ns per process (precision "process", jobs
// startup-cold and startup-warm), ns per sample of a whole command (sample-npy, histogram) and of its
// parts (npy-file-floor, histogram-binning), ns per call of an enqueue (precision "host").
std::vector<CsvRow> process_rows(const BenchReport& r)
{
    std::vector<CsvRow> rows;
    if (r.startup.measured) {
        rows.push_back({row_of("ggx", "process", "startup-cold", Timing{r.startup.cold_ms * 1e6,
                                                                              r.startup.cold_ms * 1e6,
                                                                              r.startup.cold_ms * 1e6}), 1});
        const Timing& warm = r.startup.warm_ms;
        rows.push_back({row_of("ggx", "process", "startup-warm", Timing{warm.median * 1e6, warm.low * 1e6,
                                                                              warm.high * 1e6}), 1});
    }
    if (r.apps.measured) {
        const double binning = r.apps.histogram_device;
        rows.push_back({row_of("caps", "process", "sample-npy", r.apps.sample_npy), r.apps.count});
        rows.push_back({row_of("caps", "process", "histogram", r.apps.histogram), r.apps.count});
        rows.push_back({row_of("caps", "process", "npy-file-floor", r.apps.npy_file_floor), r.apps.count});
        rows.push_back({row_of("caps", "process", "histogram-binning", Timing{binning, binning, binning}),
                        r.apps.count});
    }
    if (r.enqueue.measured) {
        const Timing& us = r.enqueue.host_us;
        const double first = r.enqueue.second_sampler_first_us * 1e3;
        rows.push_back({row_of("caps", "host", "enqueue", Timing{us.median * 1e3, us.low * 1e3, us.high * 1e3}),
                        r.enqueue.count});
        rows.push_back({row_of("caps", "host", "enqueue-second-sampler-first", Timing{first, first, first}),
                        r.enqueue.count});
        auto ns = [](const Timing& t) { return Timing{t.median * 1e3, t.low * 1e3, t.high * 1e3}; };
        rows.push_back({row_of("caps", "host", "enqueue-finish", ns(r.enqueue.at_zero_us)), r.enqueue.count});
        rows.push_back({row_of("caps", "host", "enqueue-finish-offset-" + std::to_string(r.enqueue.odd_offset),
                               ns(r.enqueue.at_odd_offset_us)),
                        r.enqueue.count});
    }
    return rows;
}

void write_csv_row(std::ostream& csv, const BenchRow& row, const BenchReport& r, std::uint64_t samples_per_run)
{
    csv << row.method << "," << row.precision << "," << row.job << "," << row.timing.median << "," << row.timing.low
        << "," << row.timing.high << "," << 1.0 / row.timing.median << ",";
    if (row.has_error)
        csv << row.error.angle_p99 << "," << row.error.angle_max << "," << row.error.pdf_p99 << ","
            << row.error.pdf_max << ",";
    else
        csv << ",,,,";
    if (row.variance > 0)
        csv << row.variance << "," << row.mean_albedo << "," << efficiency(row) << "," << rmse_at_budget(row, r);
    else
        csv << ",,,";
    csv << "," << row.sequence << ",";
    if (row.rmse_measured > 0)
        csv << row.rmse_measured;
    csv << ",";
    if (row.pdf_disagreement >= 0)
        csv << row.pdf_disagreement;
    csv << dielectric_csv_cells(row) << "," << samples_per_run << "," << row.api << "\n";
}

} // namespace

std::string bench_csv(const BenchReport& r, bool with_process_rows)
{
    std::ostringstream csv;
    csv << std::setprecision(6)
        << "method,precision,job,ns_median,ns_min,ns_max,gsamples_per_s,angle_p99,angle_max,pdf_rel_p99,pdf_rel_max,"
           "albedo_variance,mean_albedo,efficiency,rmse_at_budget,sequence,rmse_measured,pdf_disagreement"
        << dielectric_csv_header << ",samples_per_run,api\n";
    for (const BenchRow& row : r.rows)
        write_csv_row(csv, row, r, row.precision == "native" ? r.native_count : r.count);
    if (r.has_vectorized)
        csv << "caps,native-vectorized,furnace," << r.vectorized.median << "," << r.vectorized.low << ","
            << r.vectorized.high << "," << 1.0 / r.vectorized.median << ",,,,,,,,,philox,,"
            << dielectric_csv_cells(BenchRow{}) << "," << r.native_count << ",native\n";
    if (with_process_rows)
        for (CsvRow row : process_rows(r)) {
            row.row.api = r.devices.empty() ? "" : r.devices.front().api;  // the processes ran on the first device
            write_csv_row(csv, row.row, r, row.samples_per_run);
        }
    return csv.str();
}

// The user samplers' pdf self-consistency (precise philox write rows), when there are any.
void write_user_pdf_section(std::ostringstream& md, const BenchReport& r)
{
    std::vector<const BenchRow*> rows;
    for (const BenchRow& row : r.rows)
        if (row.pdf_disagreement >= 0)
            rows.push_back(&row);
    if (rows.empty())
        return;
    md << "\n## Your samplers: pdf self-consistency\n\nOver the numerical error's configurations, the fraction "
          "of samples with a density whose pdf_o differs by more than 1e-3 (relative) from the sampler's own pdf "
          "recomputed from (i, o): 0 for a sampler whose pdf function matches what it samples.\n\n"
          "| sampler | precision | pdf_o off its pdf(i, o) |\n|---|---|---|\n";
    for (const BenchRow* row : rows)
        md << "| " << row->method << " | " << row->precision << " | " << readable_number(row->pdf_disagreement) << " |\n";
}

namespace {

// The sections of one device: the answer, its speed, the dielectric's and its accuracy.
void write_device_sections(std::ostringstream& md, const BenchReport& r, const ChartFiles& charts)
{
    write_answer(md, r);
    md << "\n## Speed (ns per sample)\n\n";
    write_speed_table(md, r);
    if (r.eta != 0.0f)
        write_dielectric_section(md, r);
    md << "\n## Speed against numerical error\n\nDevice samples against the double-precision reference on the same "
          "uniforms (alpha 0.05, 0.3, 1 x view 0, 45, 80 degrees, 8192 samples each): angle between m's and "
          "between o's, relative error of pdf_m and pdf_o (native: m and pdf_m, the fields it writes).\n\n";
    if (!charts.speed_error.empty())
        md << "![ns per sample against numerical error](" << charts.speed_error << ")\n\n";
    write_accuracy_tables(md, r);
    md << "\n## Speed against statistical error: the albedo table\n\nThe white-furnace (albedo) estimator over a "
       << r.scene_size << " x " << r.scene_size << " table of views (cos theta = (k + 1/2)/" << r.scene_size
       << ") and roughnesses (alpha = (k + 1/2)/" << r.scene_size << "), " << r.samples_per_cell
       << " samples per cell: the per-sample variance averaged over the cells, the efficiency 1/(variance x time) "
          "with the fused estimator's time, and the RMSE per cell when the whole table gets "
       << r.budget_ms << " ms.\n\n";
    if (!charts.speed_rmse.empty())
        md << "![ns per sample against RMSE at equal time](" << charts.speed_rmse << ")\n\n";
    write_variance_table(md, r);
    md << "\n## Sequences: independent uniforms against Sobol points\n\nPrecise mode with each sequence of "
          "uniforms (SampleParams::sequence): the write and fused jobs' speed, the numerical error (each sample "
          "against the reference on the uniforms it used), and the albedo table's RMSE per cell when the whole "
          "table gets "
       << r.budget_ms << " ms at that fused speed, measured against the table's exact albedos over "
       << r.rmse_streams << " independent streams per cell (for Sobol points, scrambles); the variance model above "
          "holds for independent uniforms only. The RMSE chart plots Sobol rows with hollow markers at their "
          "measured RMSE.\n\n";
    write_sequence_table(md, r);
    write_user_pdf_section(md, r);
}

// Each row of the first device beside the same row on the others: ns per sample and the ratio.
void write_api_comparison(std::ostringstream& md, const BenchReport& r)
{
    const std::string& first = r.devices.front().api;
    md << "\n# The APIs side by side\n\nThe same rows timed in the same interleaved rounds, ns per sample (each "
          "device by its own clock, above), and each API's time over " << first << "'s.\n\n"
       << "| method | precision | job | sequence | eta |";
    for (const BenchDeviceNote& d : r.devices)
        md << " " << d.api << ": ns |";
    for (std::size_t k = 1; k < r.devices.size(); ++k)
        md << " " << r.devices[k].api << " / " << first << " |";
    md << "\n|---|---|---|---|---|";
    for (std::size_t k = 1; k < 2 * r.devices.size(); ++k)
        md << "---|";
    md << "\n";
    for (const BenchRow& row : r.rows) {
        if (row.api != first)
            continue;
        md << "| " << row.method << " | " << row.precision << " | " << row.job << " | " << row.sequence << " | "
           << row.eta << " | " << fixed(row.timing.median, 2) << " |";
        std::string ratios;
        for (std::size_t k = 1; k < r.devices.size(); ++k) {
            const BenchRow* other = nullptr;
            for (const BenchRow& o : r.rows)
                if (o.api == r.devices[k].api && o.method == row.method && o.precision == row.precision &&
                    o.job == row.job && o.sequence == row.sequence && o.eta == row.eta)
                    other = &o;
            md << " " << (other ? fixed(other->timing.median, 2) : "–") << " |";
            ratios += " " + (other ? fixed(ratio(other, &row), 2) + "x" : std::string("–")) + " |";
        }
        md << ratios << "\n";
    }
}

} // namespace

BenchReport device_report(const BenchReport& r, const std::string& api)
{
    BenchReport one = r;
    one.rows.clear();
    for (const BenchRow& row : r.rows)
        if (row.api == api || row.precision == "native")
            one.rows.push_back(row);
    one.devices.clear();
    for (const BenchDeviceNote& d : r.devices)
        if (d.api == api)
            one.devices.push_back(d);
    return one;
}

std::string bench_markdown(const BenchReport& r, const std::vector<ChartFiles>& charts)
{
    std::ostringstream md;
    const bool several = r.devices.size() > 1;
    md << "# ggx bench: the samplers on this device\n\nWritten by `ggx bench`; the command below runs it again.\n\n"
       << "- Command: `" << r.command << "`\n- Date: " << r.date << "\n- Machine: " << r.machine << "\n";
    for (const BenchDeviceNote& d : r.devices)
        md << "- Device: " << d.label << (several ? ", timed " + d.clock : "") << "\n";
    md << "- Speed runs: alpha " << r.alpha << ", view at " << r.theta << " degrees, " << r.count
       << " samples per run (world job: per-sample normals and views, at most 2^22), median of " << r.repeats
       << " runs after a warm-up, " << (several ? "each device's rows in the same interleaved rounds" : r.devices.front().clock)
       << "; (min–max) in brackets.\n- Native C++ baseline: ";
    if (r.native_unavailable.empty())
        md << r.native_count << " samples per run, " << r.threads << " threads, wall clock, median of " << r.repeats
           << " (the child process ggx-native).\n\n";
    else
        md << "not available (" << r.native_unavailable << "); no native rows.\n\n";
    for (std::size_t k = 0; k < r.devices.size(); ++k) {
        if (several)
            md << "\n# On " << r.devices[k].label << "\n\n";
        write_device_sections(md, device_report(r, r.devices[k].api), k < charts.size() ? charts[k] : ChartFiles{});
    }
    if (several)
        write_api_comparison(md, r);
    if (r.startup.measured)
        md << "\n## Start-up\n\nProcess start to first result (`ggx sample -n 1` on " << r.devices.front().label << "): " << fixed(r.startup.cold_ms, 0)
           << " ms with an empty kernel cache, " << fixed(r.startup.warm_ms.median, 0) << " ms warm (median; "
           << fixed(r.startup.warm_ms.low, 0) << "–" << fixed(r.startup.warm_ms.high, 0) << ").\n";
    if (r.enqueue.measured)
        md << "\n## Small batches\n\nHost time of one `Sampler::enqueue` of " << r.enqueue.count
           << " caps samples (m and pdf_m into the caller's buffers), caches warm, median of " << r.enqueue.calls
           << " calls: " << timing_text(r.enqueue.host_us, 1) << " us; the first call of a second Sampler on the same context, whose "
           << "programs are shared: " << fixed(r.enqueue.second_sampler_first_us, 0) << " us. An enqueue and its "
           << "finish with the buffers at offset 0: " << fixed(r.enqueue.at_zero_us.median, 1) << " us; at offset "
           << r.enqueue.odd_offset << " (the kernels take the offset: no sub-buffer, no copy), alternated with it: "
           << fixed(r.enqueue.at_odd_offset_us.median, 1) << " us.\n";
    if (r.apps.measured)
        md << "\n## The commands, whole process\n\nWall clock from process start to exit, ns per sample, caps, files "
              "in "
           << r.apps.folder << ": `ggx sample --fields m,pdf_m` into .npy " << timing_text(r.apps.sample_npy, 2) << " and `ggx "
           << "histogram --no-png` (its expected counts by quadrature included) " << timing_text(r.apps.histogram, 2) << ", " << r.apps.count
           << " samples, median of 5 runs; at " << r.apps.text_count << " samples, one run each: .csv "
           << fixed(r.apps.sample_csv, 1) << ", .ply (m) " << fixed(r.apps.sample_ply, 1) << ".\n\n"
           << "Beside them: writing the .npy's bytes (16 per sample) from memory into a new file in the same folder, "
              "1 MiB per write, "
           << timing_text(r.apps.npy_file_floor, 2) << " ns per sample, the cost of the file alone; the histogram's binning alone "
              "(sampling, binning and counting on the device, from its sidecar's device_seconds) "
           << fixed(r.apps.histogram_device, 2) << " ns.\n";
    return md.str();
}

} // namespace ggxapp
