// bench_report.cpp - CSV and Markdown of `ggx bench`, with the target checks.
#include "bench_report.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <thread>

namespace ggxapp {

namespace {

const char* const method_order[] = {"ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded"};
const char* const device_modes[] = {"precise", "fast", "relaxed"};

const BenchRow* find_row(const BenchReport& r, const std::string& method, const std::string& precision,
                         const std::string& job)
{
    for (const BenchRow& row : r.rows)
        if (row.method == method && row.precision == precision && row.job == job)
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

// The faster of the fast and relaxed rows of (method, job): the mode a speed target is met in.
const BenchRow* fastest(const BenchReport& r, const std::string& method, const std::string& job)
{
    const BenchRow* best = nullptr;
    for (const char* mode : {"fast", "relaxed"}) {
        const BenchRow* row = find_row(r, method, mode, job);
        if (row && (!best || row->timing.median < best->timing.median))
            best = row;
    }
    return best;
}

struct Target {
    std::string what, measured;
    bool met;
};

std::vector<Target> speed_targets(const BenchReport& r)
{
    std::vector<Target> out;
    const BenchRow* caps = fastest(r, "caps", "write");
    const BenchRow* heitz = fastest(r, "heitz", "write");
    if (caps)
        out.push_back({"caps >= 0.70 G samples/s (m + pdf_m written)",
                       fixed(gsps(caps), 3) + " G/s (" + caps->precision + ")", gsps(caps) >= 0.70});
    if (heitz)
        out.push_back({"heitz >= 0.45 G samples/s", fixed(gsps(heitz), 3) + " G/s (" + heitz->precision + ")",
                       gsps(heitz) >= 0.45});
    if (caps && heitz)
        out.push_back({"caps / heitz speed >= 1.4 (paper: 1.38 on a CPU)",
                       fixed(heitz->timing.median / caps->timing.median, 2), heitz->timing.median / caps->timing.median >= 1.4});
    if (caps) {
        double worst = 0;
        std::string who;
        for (const char* m : method_order) {
            const BenchRow* row = find_row(r, m, caps->precision, "write");
            if (row && row->timing.median / caps->timing.median > worst)
                worst = row->timing.median / caps->timing.median, who = m;
        }
        out.push_back({"every method within 2x of caps", "slowest " + who + ": " + fixed(worst, 2) + "x", worst <= 2.0});
    }
    double lowest = 1e300;
    std::string who;
    for (const char* m : method_order) {
        const BenchRow* device = fastest(r, m, "write");
        const BenchRow* native = find_row(r, m, "native", "write");
        if (device && native && native->timing.median / device->timing.median < lowest)
            lowest = native->timing.median / device->timing.median, who = m;
    }
    if (lowest < 1e300)
        out.push_back({"every method >= 10x the native C++ baseline (write)", "lowest " + who + ": " + fixed(lowest, 1) + "x",
                       lowest >= 10.0});
    const BenchRow* caps_world = fastest(r, "caps", "world");
    const BenchRow* iso_world = fastest(r, "caps-iso", "world");
    if (caps_world && iso_world)
        out.push_back({"caps-iso >= 1.1x caps with a basis, world space (blog: 1.15)",
                       fixed(caps_world->timing.median / iso_world->timing.median, 2) + "x",
                       caps_world->timing.median / iso_world->timing.median >= 1.1});
    const BenchRow* fused = fastest(r, "caps", "furnace");
    if (r.has_ceiling && fused)
        out.push_back({"fused caps estimator >= 60% of the hand-vectorized native ceiling",
                       fixed(100.0 * r.ceiling.median / fused->timing.median, 0) + "% (ceiling " +
                           fixed(r.ceiling.median, 2) + " ns, fused " + fixed(fused->timing.median, 2) + " ns)",
                       r.ceiling.median / fused->timing.median >= 0.6});
    double worst_guard = -1e300;
    std::string guard_who;
    for (const char* m : method_order) {
        const BenchRow* on = find_row(r, m, "fast", "write");
        const BenchRow* off = find_row(r, m, "fast-unguarded", "write");
        if (on && off && on->timing.median / off->timing.median - 1.0 > worst_guard)
            worst_guard = on->timing.median / off->timing.median - 1.0, guard_who = m;
    }
    if (worst_guard > -1e300)
        out.push_back({"guards cost < 5% (issue 5; fast, write)",
                       "largest " + guard_who + ": " + fixed(100.0 * worst_guard, 1) + "%", worst_guard < 0.05});
    if (r.startup.measured) {
        out.push_back({"process start to first result <= 100 ms, warm kernel cache",
                       fixed(r.startup.warm_ms.median, 0) + " ms", r.startup.warm_ms.median <= 100});
        out.push_back({"cold build <= 1.5 s", fixed(r.startup.cold_ms, 0) + " ms", r.startup.cold_ms <= 1500});
    }
    return out;
}

void write_speed_table(std::ostream& md, const BenchReport& r)
{
    md << "| method | precision | write m + pdf_m: ns | G samples/s | fused furnace: ns | world space o: ns |\n"
          "|---|---|---|---|---|---|\n";
    for (const char* m : method_order)
        for (const char* mode : {"precise", "fast", "fast-unguarded", "relaxed", "native"}) {
            const BenchRow* w = find_row(r, m, mode, "write");
            if (!w)
                continue;
            md << "| " << m << " | " << mode << " | " << ns_cell(w) << " | " << fixed(gsps(w), 3) << " | "
               << ns_cell(find_row(r, m, mode, "furnace")) << " | " << ns_cell(find_row(r, m, mode, "world")) << " |\n";
        }
    if (r.has_ceiling)
        md << "| caps | native, hand-vectorized | – | – | " << fixed(r.ceiling.median, 2) << " (" << fixed(r.ceiling.low, 2)
           << "–" << fixed(r.ceiling.high, 2) << ") | – |\n";
}

void write_accuracy_tables(std::ostream& md, const BenchReport& r)
{
    md << "| method | precision | angle p99 (rad) | angle max | pdf rel. p99 | pdf rel. max |\n|---|---|---|---|---|---|\n";
    for (const char* m : method_order)
        for (const char* mode : {"precise", "fast", "relaxed", "native"}) {
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
    for (const char* m : method_order)
        for (const char* mode : device_modes) {
            const BenchRow* f = find_row(r, m, mode, "furnace");
            if (f && f->variance > 0)
                md << "| " << m << " | " << mode << " | " << fixed(f->variance, 5) << " | " << fixed(f->mean_albedo, 5) << " | "
                   << fixed(f->timing.median, 2) << " | " << sci(efficiency(*f)) << " | " << sci(rmse_at_budget(*f, r))
                   << " |\n";
        }
}

} // namespace

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
    std::ostringstream csv;
    csv << std::setprecision(6)
        << "method,precision,job,ns_median,ns_min,ns_max,gsamples_per_s,angle_p99,angle_max,pdf_rel_p99,pdf_rel_max,"
           "albedo_variance,mean_albedo,efficiency,rmse_at_budget\n";
    for (const BenchRow& row : r.rows) {
        csv << row.method << "," << row.precision << "," << row.job << "," << row.timing.median << ","
            << row.timing.low << "," << row.timing.high << "," << 1.0 / row.timing.median << ",";
        if (row.has_error)
            csv << row.error.angle_p99 << "," << row.error.angle_max << "," << row.error.pdf_p99 << ","
                << row.error.pdf_max << ",";
        else
            csv << ",,,,";
        if (row.variance > 0)
            csv << row.variance << "," << row.mean_albedo << "," << efficiency(row) << "," << rmse_at_budget(row, r)
                << "\n";
        else
            csv << ",,,\n";
    }
    if (r.has_ceiling)
        csv << "caps,native-vectorized,furnace," << r.ceiling.median << "," << r.ceiling.low << "," << r.ceiling.high
            << "," << 1.0 / r.ceiling.median << ",,,,,,,,\n";
    return csv.str();
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
    if (r.startup.measured)
        md << "\n## Start-up\n\nProcess start to first result (`ggx sample -n 1`): " << fixed(r.startup.cold_ms, 0)
           << " ms with an empty kernel cache, " << fixed(r.startup.warm_ms.median, 0) << " ms warm (median; "
           << fixed(r.startup.warm_ms.low, 0) << "–" << fixed(r.startup.warm_ms.high, 0) << ").\n";
    return md.str();
}

} // namespace ggxapp
