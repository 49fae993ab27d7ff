// limits_main.cpp - ggx-limits, the project's own measure of how close each method runs to this
// device's limits (docs/COST-PROBES.md, "How close to the limit"; bench/check_targets.py reads its
// CSV): every method's precise write and fused (furnace) jobs timed as `ggx bench` times them
// (bench_speed.hpp, interleaved rounds), beside the store-only kernel; their operations per sample
// counted in their LLVM IR (clang: bench_ops.hpp) and the device's peaks measured in a child process
// of this tool (`ggx-limits --peak-probe`, bench_peak.hpp).  OpenCL devices only.
//   ggx-limits [--device SEL] [--methods LIST] [--alpha A] [--theta DEG] [-n COUNT] [--repeats N]
//              [--csv FILE] [--markdown FILE]
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "atomic_file.hpp"
#include "bench_limits.hpp"
#include "bench_ops.hpp"
#include "bench_peak.hpp"
#include "cli_values.hpp"
#include "library_errors.hpp"

namespace {

using namespace ggxapp;

struct LimitsCommand {
    std::string device, methods = "all", alpha = "0.3", theta = "60", count = "2^24", repeats = "7", csv, markdown;
    bool peak_probe = false;
};

// Seconds the peak probe's child may take, its build included (a GPU's takes about one).
constexpr double peak_probe_limit_s = 60;

// The command's values, checked before any device work.
struct LimitsPlan {
    std::vector<ggxcl::Method> methods;
    ggxcl::SampleParams base;
    std::uint32_t count = 0;
    int repeats = 0;
};

LimitsPlan plan_of(const LimitsCommand& cmd)
{
    LimitsPlan plan;
    plan.methods.assign(std::begin(ggxcl::all_methods), std::end(ggxcl::all_methods));
    if (cmd.methods != "all") {
        plan.methods.clear();
        for (const std::string& name : split_list(cmd.methods))
            plan.methods.push_back(parse_method_option("--methods", name));
    }
    plan.base.alpha_x = plan.base.alpha_y = parse_alpha("--alpha", cmd.alpha)[0];
    plan.base.view = ggxcl::view_from_angles(parse_angle("--theta", cmd.theta, 0, 89), 0.0);
    plan.base.precision = ggxcl::Precision::precise;
    plan.count = std::uint32_t(parse_whole("-n", std::to_string(parse_count("-n", cmd.count)), 1, 1u << 30));
    plan.repeats = int(parse_whole("--repeats", cmd.repeats, 5, 101));
    return plan;
}

// Each method's precise write and furnace tasks, then the store-only kernel's.
std::vector<BenchTask> limit_tasks(const LimitsPlan& plan, BenchDevice& device)
{
    std::vector<BenchTask> tasks;
    for (ggxcl::Method method : plan.methods) {
        ggxcl::SampleParams p = plan.base;
        p.method = method;
        tasks.push_back({BenchJob::write, p, &device});
        tasks.push_back({BenchJob::furnace, p, &device});
    }
    tasks.push_back({BenchJob::store, plan.base, &device});
    return tasks;
}

LimitReport measure_limits(const LimitsPlan& plan, const std::string& selector)
{
    ApiChoice choice;
    choice.selector = selector;
    BenchDevice device = open_bench_device(choice, plan.count, {});  // OpenCL: ApiChoice's default
    const std::vector<BenchTask> tasks = limit_tasks(plan, device);
    LimitReport report;
    report.device = device.label();
    std::cerr << "counting the operations of the kernels (clang)\n";
    const std::vector<std::optional<OpCounts>> ops = count_task_ops(tasks, report.ops_unavailable);
    if (report.ops_unavailable.empty()) {  // without op counts the peaks divide nothing
        std::cerr << "measuring the device's peaks (a child process, at most " << peak_probe_limit_s << " s)\n";
        try {
            report.peaks = measure_peaks_in_child(selector, peak_probe_limit_s);
            report.has_peaks = true;
        } catch (const std::exception& e) {
            report.peaks_unavailable = e.what();
        }
    }
    std::cerr << "timing " << tasks.size() << " rows, " << plan.repeats << " interleaved rounds\n";
    const std::vector<Timing> timings = time_interleaved(tasks, plan.repeats);
    for (std::size_t t = 0; t < tasks.size(); ++t) {
        const bool store = tasks[t].job == BenchJob::store;
        report.rows.push_back({store ? row_of("all", "store-only", "write", timings[t])  // the bench's name of it
                                     : row_of(std::string(ggxcl::method_name(tasks[t].params.method)), "precise",
                                              job_name(tasks[t].job), timings[t]),
                               ops[t]});
    }
    return report;
}

} // namespace

int main(int argc, char** argv)
{
    LimitsCommand cmd;
    CLI::App app{"ggx-limits: how close each method's precise write and furnace jobs run to this OpenCL device's "
                 "compute and bandwidth limits"};
    app.add_option("--device", cmd.device, "OpenCL device index or name part (see `ggx devices`)");
    app.add_option("--methods", cmd.methods, "methods, comma-separated, or all");
    app.add_option("--alpha", cmd.alpha, "GGX roughness of the timed runs")->capture_default_str();
    app.add_option("--theta", cmd.theta, "view polar angle of the timed runs, degrees, 0..89")->capture_default_str();
    app.add_option("-n", cmd.count, "samples per timed run, up to 2^30")->capture_default_str();
    app.add_option("--repeats", cmd.repeats, "timed runs per row, 5..101 (median reported)")->capture_default_str();
    app.add_option("--csv", cmd.csv, "write the rows as CSV (what bench/check_targets.py --limits reads)");
    app.add_option("--markdown", cmd.markdown, "write the report to this file as well");
    app.add_flag("--peak-probe", cmd.peak_probe, "print the device's peaks (run by ggx-limits itself)")->group("");
    CLI11_PARSE(app, argc, argv);
    try {
        if (cmd.peak_probe) {
            ggxcl::Sampler sampler(cmd.device);
            std::cout << peak_rates_text(measure_peaks(sampler)) << std::flush;
            return 0;
        }
        const LimitsPlan plan = plan_of(cmd);
        install_interrupt_cleanup();
        const LimitReport report = measure_limits(plan, cmd.device);
        std::ostringstream md;
        write_limit_section(md, report);
        std::cout << md.str();
        if (!cmd.csv.empty())
            write_text_file(cmd.csv, limits_csv(report));
        if (!cmd.markdown.empty())
            write_text_file(cmd.markdown, md.str());
    } catch (const std::exception& e) {
        std::cerr << "ggx-limits: " << e.what() << "\n";
        return 1;
    }
}
