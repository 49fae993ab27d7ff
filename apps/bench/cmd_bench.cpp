// cmd_bench.cpp - `ggx bench`: speed against accuracy of every method in
// every precision mode on a device, side by side with the native C++
// baseline: ns per sample of three jobs (m + pdf_m written, the fused
// white-furnace estimator, world-space sampling; with --eta a rough
// dielectric's beside the conductor's), numerical error against
// the reference, the variance of the albedo estimator over a small table,
// efficiency and RMSE at equal time, start-up time.  Prints the Markdown
// report; --csv, --charts, --markdown and --html write the CSV, the two PNG
// charts, the report and its page (docs/BENCHMARKS.md is made by it, with
// the project's targets from bench/check_targets.py).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "atomic_file.hpp"
#include "bench_accuracy.hpp"
#include "user_checks.hpp"
#include "bench_native.hpp"
#include "bench_ops.hpp"
#include "bench_peak.hpp"
#include "bench_plan.hpp"
#include "bench_report.hpp"
#include "bench_startup.hpp"
#include "api_options.hpp"
#include "bench_apps.hpp"
#include "bench_vulkan.hpp"
#include "bench_enqueue.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "html_page.hpp"
#include "plot.hpp"
#include "report_text.hpp"

namespace ggxapp {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Seconds the peak probe's child may take, its build included (a GPU's takes about one).
constexpr double peak_probe_limit_s = 60;

// What the limits need, before any timing: the tasks' op counts (clang, in parallel) and then the
// device's peaks (bench_limits.hpp), measured in a child process with a time limit.  Neither stops
// the bench when it fails or runs past its time: the report says why.
std::vector<std::optional<OpCounts>> measure_limit_inputs(ggxcl::Sampler& sampler, const std::string& device,
                                                          const std::vector<BenchTask>& tasks, BenchReport& report)
{
    auto start = std::chrono::steady_clock::now();
    std::cerr << "counting the operations of " << tasks.size() << " device rows' kernels (clang)\n";
    std::vector<std::optional<OpCounts>> ops = count_task_ops(sampler, tasks, report.ops_unavailable);
    std::cerr << "op counts: " << (report.ops_unavailable.empty() ? "" : "unavailable (" + report.ops_unavailable + "), ")
              << seconds_since(start) << " s\n";
    std::cerr << "measuring the device's peaks (a child process, at most " << peak_probe_limit_s << " s)\n";
    try {
        report.peaks = measure_peaks_in_child(device, peak_probe_limit_s);
        report.has_peaks = true;
        std::cerr << "peak probe: " << report.peaks.seconds << " s\n";
    } catch (const std::exception& e) {
        report.peaks_unavailable = e.what();
        std::cerr << "peak probe unavailable: " << e.what() << "\n";
    }
    return ops;
}

// The conductor's tasks: every method x precision x job, the guards' cost and the other
// sequences side by side.
void add_conductor_tasks(const BenchPlan& plan, std::vector<BenchTask>& tasks)
{
    for (const std::string& mode : plan.precisions)
        for (const std::string& name : plan.methods)
            for (const std::string& job_text : plan.jobs) {
                ggxcl::SampleParams p = plan.base;
                p.method = ggxcl::parse_method(name);
                p.precision = ggxcl::parse_precision(mode);
                tasks.push_back({job_named(job_text), p});
                if (mode == "precise" && job_text == "write") {  // the guards' cost, side by side
                    ggxcl::SampleParams unguarded = p;
                    unguarded.guards = false;
                    tasks.push_back({BenchJob::write, unguarded});
                }
                if (job_text == "write" || job_text == "furnace")
                    for (const ggxcl::SampleParams& other : other_sequences(plan, p))
                        tasks.push_back({job_named(job_text), other});
            }
}

// A user sampler's tasks, after the methods': every precision x job but world (a user sampler
// works in tangent space), the other sequences side by side.
void add_user_tasks(const BenchPlan& plan, std::vector<BenchTask>& tasks)
{
    for (const BenchUserSampler& user : plan.users)
        for (const std::string& mode : plan.precisions)
            for (const std::string& job_text : plan.jobs) {
                if (job_text == "world")
                    continue;
                ggxcl::SampleParams p = plan.base;
                p.method = ggxcl::Method::user;
                p.user_sampler = user.sampler;
                p.precision = ggxcl::parse_precision(mode);
                tasks.push_back({job_named(job_text), p});
                if (job_text == "write" || job_text == "furnace")
                    for (const ggxcl::SampleParams& other : other_sequences(plan, p))
                        tasks.push_back({job_named(job_text), other});
            }
}

bool plans_job(const BenchPlan& plan, const char* job)
{
    return std::find(plan.jobs.begin(), plan.jobs.end(), job) != plan.jobs.end();
}

// With --eta, every method but bounded as a dielectric: o + pdf_o written (beside the conductor
// writing the same) and the fused furnace (beside the conductor's furnace task), philox.
void add_dielectric_tasks(const BenchPlan& plan, std::vector<BenchTask>& tasks)
{
    if (plan.settings.eta == 0.0f)
        return;
    for (const std::string& mode : plan.precisions)
        for (const std::string& name : plan.methods) {
            ggxcl::SampleParams conductor = plan.base;
            conductor.method = ggxcl::parse_method(name);
            conductor.precision = ggxcl::parse_precision(mode);
            if (!ggxcl::method_traits(conductor.method).dielectric)
                continue;
            ggxcl::SampleParams dielectric = conductor;
            dielectric.eta = plan.settings.eta;
            dielectric.transport = plan.transport;
            if (plans_job(plan, "write")) {
                tasks.push_back({BenchJob::write_o, conductor});
                tasks.push_back({BenchJob::write_o, dielectric});
            }
            if (plans_job(plan, "furnace"))
                tasks.push_back({BenchJob::furnace, dielectric});
        }
}

std::vector<BenchTask> bench_tasks(const BenchPlan& plan)
{
    std::vector<BenchTask> tasks;
    add_conductor_tasks(plan, tasks);
    add_user_tasks(plan, tasks);
    add_dielectric_tasks(plan, tasks);
    if (plans_job(plan, "write"))  // the write job's ceiling, once: the same bytes stored, nothing computed
        tasks.push_back({BenchJob::store, plan.base});
    return tasks;
}

// Whether p's user sampler reproduces a built-in method's map (--reproduces), and which.
bool reproduced_method(const std::vector<BenchUserSampler>& users, const ggxcl::SampleParams& p, ggxcl::Method& method)
{
    for (const BenchUserSampler& user : users)
        if (user.sampler == p.user_sampler && user.reproduces) {
            method = user.method;
            return true;
        }
    return false;
}

// The reference's values the accuracy columns compare with, each computed once, when first needed.
struct ExactValues {
    std::vector<double> albedo_table;
    std::optional<ggxref::DielectricAlbedo> dielectric;
};

// The accuracy columns of a guarded device row: a conductor's numerical error (write), albedo
// variance and table RMSE (furnace); a dielectric furnace's reflectance and transmittance.
void add_accuracy(ggxcl::Sampler& sampler, const BenchTask& task, const BenchReport& report,
                  const std::vector<BenchUserSampler>& plan_users, ExactValues& exact, BenchRow& row)
{
    const ggxcl::SampleParams& p = task.params;
    if (p.eta != 0.0f) {
        if (task.job == BenchJob::furnace) {
            if (!exact.dielectric)
                exact.dielectric = dielectric_exact(p);
            row.dielectric = dielectric_accuracy(sampler, p, *exact.dielectric);
        }
        return;
    }
    const bool user = p.method == ggxcl::Method::user;
    ggxcl::Method reference = p.method;
    if (task.job == BenchJob::write && user && p.sequence == ggxcl::Sequence::philox)
        row.pdf_disagreement = pdf_disagreement(sampler, p);
    if (task.job == BenchJob::write && (!user || reproduced_method(plan_users, p, reference))) {
        row.has_error = true;
        row.error = numerical_error(sampler, p, reference, p.precision, p.sequence);
    }
    if (task.job == BenchJob::furnace && p.sequence == ggxcl::Sequence::philox) {
        SceneVariance scene = albedo_scene_variance(sampler, p, p.precision, report.scene_size,
                                                    report.samples_per_cell);
        row.variance = scene.variance;
        row.mean_albedo = scene.mean_albedo;
    }
    if (task.job == BenchJob::furnace && p.precision == ggxcl::Precision::precise) {
        if (exact.albedo_table.empty())
            exact.albedo_table = albedo_table(report.scene_size);
        row.rmse_measured = albedo_table_rmse(sampler, p, p.precision, p.sequence, report.scene_size,
                                              samples_at_budget(row, report), report.rmse_streams, exact.albedo_table);
    }
}

BenchRow device_row(const BenchTask& task, Timing timing)
{
    const ggxcl::SampleParams& p = task.params;
    if (task.job == BenchJob::store)
        return row_of("all", "store-only", "write", timing);
    const std::string precision(ggxcl::precision_name(p.precision));
    BenchRow row = row_of(ggxcl::sampler_name(p), task.params.guards ? precision : precision + "-unguarded",
                          job_name(task.job), timing);
    row.sequence = std::string(ggxcl::sequence_name(p.sequence));
    row.eta = p.eta;
    if (p.eta != 0.0f)
        row.transport = std::string(ggxcl::transport_name(p.transport));
    return row;
}

void measure_device(ggxcl::Sampler& sampler, const BenchPlan& plan, const BenchCommand& cmd, BenchReport& report)
{
    const std::vector<BenchTask> tasks = bench_tasks(plan);
    const std::vector<std::optional<OpCounts>> ops = measure_limit_inputs(sampler, cmd.device, tasks, report);
    std::cerr << "timing " << tasks.size() << " device rows, " << report.repeats << " interleaved rounds\n";
    DeviceTimer timer(sampler, report.count);
    std::vector<Timing> timings = timer.time_interleaved(tasks, report.repeats);
    report.device_clock = timer.clock_description();
    if (timer.wall_clock())
        std::cerr << "device rows timed by wall clock: " << report.device_clock << "\n";
    ExactValues exact;
    if (!cmd.no_accuracy)
        std::cerr << "measuring the accuracy columns\n";
    for (std::size_t t = 0; t < tasks.size(); ++t) {
        BenchRow row = device_row(tasks[t], timings[t]);
        if (ops[t])
            row.has_ops = true, row.ops = *ops[t];
        if (!cmd.no_accuracy && tasks[t].params.guards && tasks[t].job != BenchJob::store)  // unguarded: speed only
            add_accuracy(sampler, tasks[t], report, plan.users, exact, row);
        report.rows.push_back(row);
    }
}

// The native rows; their albedo variance is the device's precise one for the
// same method (the same samples, drawn from the same uniforms).  All or none:
// they join the report only once the vectorized loop is timed too.
void measure_native(const BenchPlan& plan, BenchReport& report)
{
    std::cerr << "timing the native C++ baseline (ggx-native)\n";
    NativeSetup setup{report.native_count, report.threads, report.repeats, plan.base.alpha_x, plan.base.view};
    std::vector<BenchRow> rows;
    for (const std::string& name : plan.methods) {
        ggxcl::Method method = ggxcl::parse_method(name);
        for (const std::string& job_text : plan.jobs) {
            BenchJob job = job_named(job_text);
            if (job == BenchJob::per_sample)  // the native baseline has no such job
                continue;
            BenchRow row = row_of(name, "native", job_text, native_timing(method, job, setup));
            if (job == BenchJob::write) {
                row.has_error = true;
                row.error = native_numerical_error(method);
            }
            for (const BenchRow& device : report.rows)
                if (job == BenchJob::furnace && device.method == name && device.precision == "precise" &&
                    device.job == "furnace" && device.sequence == "philox" && device.eta == 0.0f)
                    row.variance = device.variance, row.mean_albedo = device.mean_albedo;
            std::cerr << "  " << name << " native " << job_text << ": " << row.timing.median << " ns\n";
            rows.push_back(row);
        }
    }
    report.vectorized = native_vectorized_timing(ggxcl::Method::caps, setup);
    report.has_vectorized = true;
    report.rows.insert(report.rows.end(), rows.begin(), rows.end());
}

// The native baseline, or, where ggx-native is missing or fails (built for
// another CPU, say), a note in its place and no native rows, as --no-native.
void measure_native_if_available(const BenchPlan& plan, BenchReport& report)
{
    try {
        measure_native(plan, report);
    } catch (const NativeBaselineError& e) {
        report.native_unavailable = e.what();
        std::cerr << "native baseline not available (" << e.what() << "); skipping the native rows\n";
    }
}

void write_outputs(const BenchCommand& cmd, const BenchReport& report)
{
    if (!cmd.csv.empty())
        write_text_file(cmd.csv, bench_csv(report));
    std::string speed_error, speed_rmse;
    if (const std::string charts = charts_prefix(cmd.charts, cmd.html); !charts.empty()) {
        speed_error = charts + "-speed-error.png";
        speed_rmse = charts + "-speed-rmse.png";
        std::string csv_path = charts + ".plot.csv";
        write_text_file(csv_path, bench_csv(report, false));
        run_plot_script("plot_bench.py", {csv_path, speed_error, speed_rmse, report.device});
        std::filesystem::remove(csv_path);
    }
    // The report with its chart links relative to where it goes.
    const auto report_for = [&](const std::string& page) {
        return bench_markdown(report, speed_error.empty() ? "" : relative_to(speed_error, page),
                              speed_rmse.empty() ? "" : relative_to(speed_rmse, page));
    };
    std::string md = report_for(cmd.markdown);
    if (!cmd.markdown.empty())
        write_text_file(cmd.markdown, md);
    if (!cmd.html.empty())
        write_markdown_page(cmd.html, report_for(cmd.html));
    std::cout << md;
}

void run_bench(const BenchCommand& cmd, const BenchPlan& plan)
{
    for (const auto& [path, flag] : {std::pair{cmd.csv, "--csv"}, {cmd.markdown, "--markdown"}, {cmd.charts, "--charts"},
                                     {cmd.html, "--html"}})
        if (!path.empty())
            check_writable_folder(flag, path);
    BenchReport report = plan.settings;
    report.command = command_line();
    report.date = utc_now();
    report.machine = machine_description();
    ggxcl::Sampler sampler(cmd.device);
    report.device = sampler.device_name();
    measure_device(sampler, plan, cmd, report);
    if (!cmd.no_native)
        measure_native_if_available(plan, report);
    if (!cmd.no_startup) {
        std::cerr << "timing start-up, enqueue and whole commands\n";
        report.startup = measure_startup(cmd.device, 5);
        report.enqueue = measure_enqueue(sampler, plan.base);
        // Twice the device runs' count (2^25 by default): a process's fixed costs weigh as in a dataset run.
        report.apps = measure_apps(cmd.device, 2 * plan.settings.count);
    }
    write_outputs(cmd, report);
}

// --api vulkan: the write and furnace jobs on the Vulkan device beside the OpenCL one.
void run_vulkan_bench(const BenchCommand& cmd, const BenchPlan& plan, const ApiChoice& api)
{
    for (const auto& [path, flag] : {std::pair{cmd.csv, "--csv"}, {cmd.markdown, "--markdown"}})
        if (!path.empty())
            check_writable_folder(flag, path);
    const ApiBenchReport report = measure_api_bench(plan, api.selector, api.language, !cmd.no_accuracy);
    if (!cmd.csv.empty())
        write_text_file(cmd.csv, api_bench_csv(report));
    const std::string md = api_bench_markdown(report);
    if (!cmd.markdown.empty())
        write_text_file(cmd.markdown, md);
    std::cout << md;
}

// The plan of --api vulkan: its jobs (write and furnace by default), and no option it cannot honour.
BenchPlan vulkan_plan(const BenchCommand& cmd, BenchPlan plan, bool jobs_given)
{
    for (const auto& [value, flag] : {std::pair{cmd.charts, "--charts"}, {cmd.html, "--html"}})
        if (!value.empty())
            throw UsageError(flag, value, "no charts or page with --api vulkan (its report is --markdown and --csv)");
    plan.jobs = vulkan_bench_jobs(plan.jobs, jobs_given);
    return plan;
}

// The speed runs: every method in every precision mode, and with --eta every method but bounded
// as a dielectric.
std::vector<Batch> timed_batches(const BenchPlan& plan)
{
    std::vector<Batch> batches;
    for (const std::string& mode : plan.precisions)
        for (const std::string& name : plan.methods) {
            ggxcl::SampleParams p = plan.base;
            p.method = ggxcl::parse_method(name);
            p.precision = ggxcl::parse_precision(mode);
            batches.push_back({p, {0, 0, plan.settings.count}});
            if (plan.settings.eta == 0.0f || !ggxcl::method_traits(p.method).dielectric)
                continue;
            p.eta = plan.settings.eta;
            p.transport = plan.transport;
            batches.push_back({p, {0, 0, plan.settings.count}});
        }
    for (const BenchUserSampler& user : plan.users) {
        ggxcl::SampleParams p = plan.base;
        p.method = ggxcl::Method::user;
        p.user_sampler = user.sampler;
        batches.push_back({p, {0, 0, plan.settings.count}});
    }
    return batches;
}

} // namespace

Prepare add_bench_command(CLI::App& app)
{
    auto s = std::make_shared<BenchCommand>();
    CLI::App* cmd = app.add_subcommand("bench", "Speed against accuracy of every method and precision mode on a device, "
                                                "beside the native C++ baseline");
    cmd->add_option("--alpha", s->alpha, "GGX roughness of the speed runs (one value)")->capture_default_str();
    cmd->add_option("--theta", s->theta, "view polar angle of the speed runs, degrees, 0..89")->capture_default_str();
    cmd->add_option("--device", s->device, "device index or name part (see `ggx devices`)");
    cmd->add_option("--methods", s->methods, "comma-separated methods, or all")->capture_default_str();
    cmd->add_option("--precisions", s->precisions, "comma-separated precision modes")->capture_default_str();
    cmd->add_option("--sequences", s->sequences, "sequences of uniforms timed in precise mode (write and furnace "
                                                 "jobs): philox (always), sobol")->capture_default_str();
    CLI::Option* jobs = cmd->add_option("--jobs", s->jobs, "comma-separated jobs: write (m + pdf_m), furnace (fused estimator), "
                                       "world (world-space o), per-sample (a view and alpha per sample read); with "
                                       "--api vulkan write and furnace")->capture_default_str();
    cmd->add_option("-n,--count", s->count, "samples per timed device run")->capture_default_str();
    cmd->add_option("--native-count", s->native_count, "samples per timed native run")->capture_default_str();
    cmd->add_option("--repeats", s->repeats, "timed runs per row, 5..101 (median reported)")->capture_default_str();
    cmd->add_option("--threads", s->threads, "threads of the native baseline")->capture_default_str();
    cmd->add_option("--scene", s->scene, "size of the albedo table (views x roughnesses)")->capture_default_str();
    cmd->add_option("--cell-samples", s->cell_samples, "samples per cell of the albedo table")->capture_default_str();
    cmd->add_option("--budget-ms", s->budget_ms, "time budget of the whole table for the RMSE column")->capture_default_str();
    cmd->add_option("--eta", s->eta, "a rough dielectric's relative index (e.g. 1.5): its write (o + pdf_o) and "
                                     "furnace rows beside the conductor's, every method but bounded; 0: none")
        ->capture_default_str();
    cmd->add_option("--transport", s->transport, "the dielectric rows' transport: radiance or importance")
        ->capture_default_str();
    s->user.add_to(*cmd);
    cmd->add_option("--reproduces", s->reproduces, "the k-th --sampler reproduces this method's map on the same "
                                                    "uniforms (or none): its numerical error against that "
                                                    "method's reference (repeatable)");
    cmd->add_flag("--no-native", s->no_native, "skip the native C++ baseline");
    cmd->add_flag("--no-accuracy", s->no_accuracy, "skip the numerical and statistical accuracy columns");
    cmd->add_flag("--no-startup", s->no_startup, "skip the start-up timing");
    cmd->add_option("--csv", s->csv, "write the rows to this CSV file");
    cmd->add_option("--charts", s->charts, "write PREFIX-speed-error.png and PREFIX-speed-rmse.png");
    cmd->add_option("--markdown", s->markdown, "write the report to this Markdown file");
    cmd->add_option("--html", s->html, "write the report as a web page (with its charts; beside it unless --charts)");
    auto api = std::make_shared<ApiOptions>();
    api->add_to(*cmd);
    return [cmd, s, api, jobs]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        const ApiChoice choice = api->choose(s->device, s->user.files);
        BenchPlan plan = plan_bench(*s, choice);
        if (choice.vulkan) {
            plan = vulkan_plan(*s, plan, jobs->count() > 0);
            return Work{[s, plan, choice] { run_vulkan_bench(*s, plan, choice); }, timed_batches(plan)};
        }
        return Work{[s, plan] { run_bench(*s, plan); }, timed_batches(plan)};
    };
}

} // namespace ggxapp
