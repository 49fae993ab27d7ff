// bench_report.cpp - CSV and Markdown of `ggx bench`, with the target checks
// and, with --eta, the rough dielectric's section.
#include "bench_report.hpp"

#include "bench_limits.hpp"

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

// A row of a conductor (eta 0) or, with dielectric, of the dielectric (eta set).
const BenchRow* find_row(const BenchReport& r, const std::string& method, const std::string& precision,
                         const std::string& job, const std::string& sequence = "philox", bool dielectric = false)
{
    for (const BenchRow& row : r.rows)
        if (row.method == method && row.precision == precision && row.job == job && row.sequence == sequence &&
            (row.eta != 0.0f) == dielectric)
            return &row;
    return nullptr;
}

std::string fixed(double value, int digits)
{
    std::ostringstream out;
    out << std::fixed << std::setprecision(digits) << value;
    return out.str();
}

std::string sci(double value)
{
    std::ostringstream out;
    out << std::setprecision(2) << std::scientific << value;
    return out.str();
}

std::string ns_cell(const BenchRow* row)
{
    if (!row)
        return "–";
    return fixed(row->timing.median, 2) + " (" + fixed(row->timing.low, 2) + "–" + fixed(row->timing.high, 2) + ")";
}

double gsps(const BenchRow* row)
{
    return row ? 1.0 / row->timing.median : 0.0;
}

// The default mode's row of (method, job): the mode the speed targets are met in.
const BenchRow* default_row(const BenchReport& r, const std::string& method, const std::string& job)
{
    return find_row(r, method, "precise", job);
}

double ratio(const BenchRow* slow, const BenchRow* fast)
{
    return slow->timing.median / fast->timing.median;
}

using Target = ReportTarget;

// Speed against the device's own limits (bench_limits.hpp), and between methods.
void rate_targets(const BenchReport& r, std::vector<Target>& out)
{
    limit_targets(r, out);
    const BenchRow* caps = default_row(r, "caps", "write");
    for (const char* job : {"write", "furnace"}) {
        const BenchRow* c = default_row(r, "caps", job);
        const BenchRow* h = default_row(r, "heitz", job);
        if (c && h)
            out.push_back({std::string("caps / heitz speed >= 1.35, ") + job + " (paper: 1.38 on a CPU)",
                           fixed(ratio(h, c), 2), ratio(h, c) >= 1.35});
    }
    if (caps) {
        double worst = 0;
        std::string who;
        for (const std::string& m : method_order(r)) {
            const BenchRow* row = default_row(r, m, "write");
            if (row && ratio(row, caps) > worst)
                worst = ratio(row, caps), who = m;
        }
        out.push_back({"every method within 2x of caps", "slowest " + who + ": " + fixed(worst, 2) + "x", worst <= 2.0});
    }
}

void mode_targets(const BenchReport& r, std::vector<Target>& out)
{
    double worst = 0;
    std::string who;
    for (const std::string& m : method_order(r))
        for (const char* job : {"write", "furnace"}) {
            const BenchRow* precise = default_row(r, m, job);
            const BenchRow* relaxed = find_row(r, m, "relaxed", job);
            if (precise && relaxed && ratio(precise, relaxed) > worst)
                worst = ratio(precise, relaxed), who = m + " " + job;
        }
    if (worst > 0)
        out.push_back({"the default (precise) within 1.15x of the fastest mode (relaxed)",
                       "largest " + who + ": " + fixed(worst, 2) + "x", worst <= 1.15});
    double worst_guard = -1e300;
    std::string guard_who;
    for (const std::string& m : method_order(r)) {
        const BenchRow* on = default_row(r, m, "write");
        const BenchRow* off = find_row(r, m, "precise-unguarded", "write");
        if (on && off && ratio(on, off) - 1.0 > worst_guard)
            worst_guard = ratio(on, off) - 1.0, guard_who = m;
    }
    if (worst_guard > -1e300)
        out.push_back({"guards cost < 5% (precise, write)",
                       "largest " + guard_who + ": " + fixed(100.0 * worst_guard, 1) + "%", worst_guard < 0.05});
}

void job_targets(const BenchReport& r, std::vector<Target>& out)
{
    const BenchRow* caps = default_row(r, "caps", "write");
    const BenchRow* store = find_row(r, "all", "store-only", "write");
    if (caps && store)
        out.push_back({"the write job within 2.5x of a kernel that stores the same bytes",
                       "caps " + fixed(caps->timing.median, 2) + " ns, store " + fixed(store->timing.median, 2) + " ns: " +
                           fixed(ratio(caps, store), 2) + "x",
                       ratio(caps, store) <= 2.5});
    double worst = 0;
    std::string who;
    for (const std::string& m : method_order(r)) {
        const BenchRow* uniform = default_row(r, m, "write");
        const BenchRow* per_sample = default_row(r, m, "per-sample");
        if (uniform && per_sample && ratio(per_sample, uniform) > worst)
            worst = ratio(per_sample, uniform), who = m;
    }
    if (worst > 0)
        out.push_back({"per-sample view and alpha within 2x of the uniform write job",
                       "largest " + who + ": " + fixed(worst, 2) + "x", worst <= 2.0});
}

void baseline_targets(const BenchReport& r, std::vector<Target>& out)
{
    double lowest = 1e300;
    std::string who;
    for (const std::string& m : method_order(r)) {
        const BenchRow* device = default_row(r, m, "write");
        const BenchRow* native = find_row(r, m, "native", "write");
        if (device && native && ratio(native, device) < lowest)
            lowest = ratio(native, device), who = m;
    }
    // What the compiler's vectorizer buys the same C++: the omp simd loop against the plain one.
    const BenchRow* scalar_furnace = find_row(r, "caps", "native", "furnace");
    const std::string by_hand = r.has_vectorized && scalar_furnace
                                    ? "; caps furnace vectorized (omp simd): " +
                                          fixed(scalar_furnace->timing.median / r.vectorized.median, 1) + "x its plain loop"
                                    : "";
    if (lowest < 1e300)
        out.push_back({"every method >= 12x the native C++ baseline (write)",
                       "lowest " + who + ": " + fixed(lowest, 1) + "x" + by_hand, lowest >= 12.0});
    const BenchRow* caps_world = default_row(r, "caps", "world");
    const BenchRow* iso_world = default_row(r, "caps-iso", "world");
    if (caps_world && iso_world)
        out.push_back({"caps-iso >= 1.1x caps with a basis, world space (blog: 1.15)",
                       fixed(ratio(caps_world, iso_world), 2) + "x", ratio(caps_world, iso_world) >= 1.1});
    const BenchRow* fused = default_row(r, "caps", "furnace");
    if (r.has_vectorized && fused)
        out.push_back({"fused caps estimator >= 90% of the vectorized native C++ (omp simd)",
                       fixed(100.0 * r.vectorized.median / fused->timing.median, 0) + "% (vectorized C++ " +
                           fixed(r.vectorized.median, 2) + " ns, fused " + fixed(fused->timing.median, 2) + " ns)",
                       r.vectorized.median / fused->timing.median >= 0.9});
}

std::vector<Target> speed_targets(const BenchReport& r)
{
    std::vector<Target> out;
    rate_targets(r, out);
    mode_targets(r, out);
    job_targets(r, out);
    baseline_targets(r, out);
    if (r.startup.measured) {
        out.push_back({"process start to first result <= 100 ms, warm kernel cache",
                       fixed(r.startup.warm_ms.median, 0) + " ms", r.startup.warm_ms.median <= 100});
        out.push_back({"cold build <= 1.5 s per variant", fixed(r.startup.cold_ms, 0) + " ms", r.startup.cold_ms <= 1500});
    }
    const BenchRow* write = default_row(r, "caps", "write");
    if (r.apps.measured && write) {
        const double file = r.apps.sample_npy.median / write->timing.median;
        const double bins = r.apps.histogram.median / write->timing.median;
        // What no writer of this file can go below: the start-up and the file's bytes written from memory.
        const double start_ns = r.startup.measured ? r.startup.warm_ms.median * 1e6 / r.apps.count : 0.0;
        const double floor = start_ns + r.apps.npy_file_floor.median;
        out.push_back({"`ggx sample` into .npy within 3x of the write job per sample, whole process",
                       fixed(r.apps.sample_npy.median, 2) + " ns: " + fixed(file, 1) + "x; its floor (" +
                           (r.startup.measured ? "start-up + " : "") + "the file's bytes written from memory) " +
                           fixed(floor, 2) + " ns: " + fixed(floor / write->timing.median, 1) + "x",
                       file <= 3.0});
        out.push_back({"`ggx histogram` within 3x of the write job per sample, whole process",
                       fixed(r.apps.histogram.median, 2) + " ns: " + fixed(bins, 1) + "x; its binning alone " +
                           fixed(r.apps.histogram_device, 2) + " ns: " +
                           fixed(r.apps.histogram_device / write->timing.median, 1) + "x",
                       bins <= 3.0});
    }
    if (r.enqueue.measured)
        out.push_back({"host time of one enqueue of " + std::to_string(r.enqueue.count) +
                           " samples < 20 us (warm, median of " + std::to_string(r.enqueue.calls) + ")",
                       fixed(r.enqueue.host_us.median, 1) + " us (" + fixed(r.enqueue.host_us.low, 1) + "–" +
                           fixed(r.enqueue.host_us.high, 1) + "); a second Sampler's first: " +
                           fixed(r.enqueue.second_sampler_first_us, 0) + " us",
                       r.enqueue.host_us.median < 20.0});
    return out;
}

void write_speed_table(std::ostream& md, const BenchReport& r)
{
    md << "| method | precision | write m + pdf_m: ns | G samples/s | fused furnace: ns | world space o: ns | "
          "per-sample view, alpha: ns |\n|---|---|---|---|---|---|---|\n";
    for (const std::string& m : method_order(r))
        for (const char* mode : {"precise", "precise-unguarded", "relaxed", "native"}) {
            const BenchRow* w = find_row(r, m, mode, "write");
            if (!w)
                continue;
            md << "| " << m << " | " << mode << " | " << ns_cell(w) << " | " << fixed(gsps(w), 3) << " | "
               << ns_cell(find_row(r, m, mode, "furnace")) << " | " << ns_cell(find_row(r, m, mode, "world")) << " | "
               << ns_cell(find_row(r, m, mode, "per-sample")) << " |\n";
        }
    if (r.has_vectorized)
        md << "| caps | native, vectorized (omp simd) | – | – | " << fixed(r.vectorized.median, 2) << " ("
           << fixed(r.vectorized.low, 2) << "–" << fixed(r.vectorized.high, 2) << ") | – | – |\n";
    if (const BenchRow* store = find_row(r, "all", "store-only", "write"))
        md << "| (none) | store only: the write job's bytes | " << ns_cell(store) << " | " << fixed(gsps(store), 3)
           << " | – | – | – |\n";
}

void write_accuracy_tables(std::ostream& md, const BenchReport& r)
{
    md << "| method | precision | angle p99 (rad) | angle max | pdf rel. p99 | pdf rel. max |\n|---|---|---|---|---|---|\n";
    for (const std::string& m : method_order(r))
        for (const char* mode : {"precise", "relaxed", "native"}) {
            const BenchRow* w = find_row(r, m, mode, "write");
            if (w && w->has_error)
                md << "| " << m << " | " << mode << " | " << sci(w->error.angle_p99) << " | " << sci(w->error.angle_max)
                   << " | " << sci(w->error.pdf_p99) << " | " << sci(w->error.pdf_max) << " |\n";
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
                   << fixed(f->timing.median, 2) << " | " << sci(efficiency(*f)) << " | " << sci(rmse_at_budget(*f, r))
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
               << (w && w->has_error ? sci(w->error.angle_p99) : "–") << " | " << samples_at_budget(*f, r) << " | "
               << sci(f->rmse_measured) << " |\n";
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
    if (std::any_of(r.rows.begin(), r.rows.end(), [](const BenchRow& row) { return row.method == "bounded"; }))
        md << "\nbounded: no dielectric rows; it has no exact dielectric sampler (its cap leaves out microfacet "
              "normals that refract, so some transmitted directions are never drawn).\n";
    write_dielectric_accuracy(md, r);
}

} // namespace

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

std::string bench_csv(const BenchReport& r)
{
    const std::string limit_header = limit_csv_header();
    const std::size_t limit_columns = std::count(limit_header.begin(), limit_header.end(), ',');
    std::ostringstream csv;
    csv << std::setprecision(6)
        << "method,precision,job,ns_median,ns_min,ns_max,gsamples_per_s,angle_p99,angle_max,pdf_rel_p99,pdf_rel_max,"
           "albedo_variance,mean_albedo,efficiency,rmse_at_budget,sequence,rmse_measured,pdf_disagreement"
        << limit_header << dielectric_csv_header << "\n";
    for (const BenchRow& row : r.rows) {
        csv << row.method << "," << row.precision << "," << row.job << "," << row.timing.median << ","
            << row.timing.low << "," << row.timing.high << "," << 1.0 / row.timing.median << ",";
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
        csv << limit_csv_cells(row, r) << dielectric_csv_cells(row) << "\n";
    }
    if (r.has_vectorized)
        csv << "caps,native-vectorized,furnace," << r.vectorized.median << "," << r.vectorized.low << ","
            << r.vectorized.high << "," << 1.0 / r.vectorized.median << ",,,,,,,,,philox,,"
            << std::string(limit_columns, ',') << dielectric_csv_cells(BenchRow{}) << "\n";
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
        md << "| " << row->method << " | " << row->precision << " | " << sci(row->pdf_disagreement) << " |\n";
}

std::string bench_markdown(const BenchReport& r, const std::string& speed_error_png, const std::string& speed_rmse_png)
{
    std::ostringstream md;
    md << "# Benchmarks\n\nWritten by `ggx bench`; regenerate it with the command below rather than editing it.\n"
          "Cost probes and earlier measurements: [COST-PROBES.md](COST-PROBES.md).\n\n"
       << "- Command: `" << r.command << "`\n- Date: " << r.date << "\n- Machine: " << r.machine
       << "\n- Device: " << r.device << "\n- Speed runs: alpha " << r.alpha << ", view at " << r.theta
       << " degrees, " << r.count << " samples per run (world job: per-sample normals and views, at most 2^22), median of "
       << r.repeats << " runs after a warm-up, " << r.device_clock << "; (min–max) in brackets.\n"
       << "- Native C++ baseline: ";
    if (r.native_unavailable.empty())
        md << r.native_count << " samples per run, " << r.threads << " threads, wall clock, median of " << r.repeats
           << " (the child process ggx-native).\n\n";
    else
        md << "not available (" << r.native_unavailable << "); no native rows.\n\n";
    md << "## Targets\n\n| target | measured | met |\n|---|---|---|\n";
    for (const Target& t : speed_targets(r))
        md << "| " << t.what << " | " << t.measured << " | " << (t.met ? "yes" : "**no**") << " |\n";
    md << "\n## Speed (ns per sample)\n\n";
    write_speed_table(md, r);
    if (r.eta != 0.0f)
        write_dielectric_section(md, r);
    write_limit_section(md, r);
    md << "\n## Speed against numerical error\n\nDevice samples against the double-precision reference on the same "
          "uniforms (alpha 0.05, 0.3, 1 x view 0, 45, 80 degrees, 8192 samples each): angle between m's and "
          "between o's, relative error of pdf_m and pdf_o (native: m and pdf_m, the fields it writes).\n\n";
    if (!speed_error_png.empty())
        md << "![ns per sample against numerical error](" << speed_error_png << ")\n\n";
    write_accuracy_tables(md, r);
    md << "\n## Speed against statistical error: the albedo table\n\nThe white-furnace (albedo) estimator over a "
       << r.scene_size << " x " << r.scene_size << " table of views (cos theta = (k + 1/2)/" << r.scene_size
       << ") and roughnesses (alpha = (k + 1/2)/" << r.scene_size << "), " << r.samples_per_cell
       << " samples per cell: the per-sample variance averaged over the cells, the efficiency 1/(variance x time) "
          "with the fused estimator's time, and the RMSE per cell when the whole table gets "
       << r.budget_ms << " ms.\n\n";
    if (!speed_rmse_png.empty())
        md << "![ns per sample against RMSE at equal time](" << speed_rmse_png << ")\n\n";
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
    if (r.startup.measured)
        md << "\n## Start-up\n\nProcess start to first result (`ggx sample -n 1`): " << fixed(r.startup.cold_ms, 0)
           << " ms with an empty kernel cache, " << fixed(r.startup.warm_ms.median, 0) << " ms warm (median; "
           << fixed(r.startup.warm_ms.low, 0) << "–" << fixed(r.startup.warm_ms.high, 0) << ").\n";
    if (r.enqueue.measured)
        md << "\n## Small batches\n\nHost time of one `Sampler::enqueue` of " << r.enqueue.count
           << " caps samples (m and pdf_m into the caller's buffers), caches warm, median of " << r.enqueue.calls
           << " calls: " << fixed(r.enqueue.host_us.median, 1) << " us (" << fixed(r.enqueue.host_us.low, 1) << "–"
           << fixed(r.enqueue.host_us.high, 1) << "); the first call of a second Sampler on the same context, whose "
           << "programs are shared: " << fixed(r.enqueue.second_sampler_first_us, 0) << " us.\n";
    if (r.apps.measured)
        md << "\n## The commands, whole process\n\nWall clock from process start to exit, ns per sample, caps, files "
              "in "
           << r.apps.folder << ": `ggx sample --fields m,pdf_m` into .npy " << fixed(r.apps.sample_npy.median, 2)
           << " (" << fixed(r.apps.sample_npy.low, 2) << "–" << fixed(r.apps.sample_npy.high, 2) << ") and `ggx "
           << "histogram --no-png` (its expected counts by quadrature included) " << fixed(r.apps.histogram.median, 2)
           << " (" << fixed(r.apps.histogram.low, 2) << "–" << fixed(r.apps.histogram.high, 2) << "), " << r.apps.count
           << " samples, median of 5 runs; at " << r.apps.text_count << " samples, one run each: .csv "
           << fixed(r.apps.sample_csv, 1) << ", .ply (m) " << fixed(r.apps.sample_ply, 1) << ".\n\n"
           << "Beside them: writing the .npy's bytes (16 per sample) from memory into a new file in the same folder, "
              "1 MiB per write, "
           << fixed(r.apps.npy_file_floor.median, 2) << " ns per sample (" << fixed(r.apps.npy_file_floor.low, 2) << "–"
           << fixed(r.apps.npy_file_floor.high, 2) << "), the cost of the file alone; the histogram's binning alone "
              "(sampling, binning and counting on the device, from its sidecar's device_seconds) "
           << fixed(r.apps.histogram_device, 2) << " ns.\n";
    return md.str();
}

} // namespace ggxapp
