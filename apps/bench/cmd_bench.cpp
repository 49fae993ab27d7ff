// cmd_bench.cpp - `ggx bench`: speed against accuracy of every method in
// every precision mode on the devices of one or both APIs (--api
// opencl,vulkan: timed in the same rounds, each device's rows with an api
// column and a section of the report), side by side with the native C++
// baseline: ns per sample of three jobs (m + pdf_m written, the fused
// white-furnace estimator, world-space sampling; with --eta a rough
// dielectric's beside the conductor's), numerical error against
// the reference, the variance of the albedo estimator over a small table,
// efficiency and RMSE at equal time, start-up time.  Prints the Markdown
// report; --csv, --charts, --markdown and --html write the CSV, the two PNG
// charts, the report and its page (docs/BENCHMARKS.md is made by it, with
// the project's targets from bench/check_targets.py).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "atomic_file.hpp"
#include "bench_accuracy.hpp"
#include "user_checks.hpp"
#include "bench_native.hpp"
#include "bench_plan.hpp"
#include "bench_report.hpp"
#include "api_options.hpp"
#include "bench_apps.hpp"
#include "bench_enqueue.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "html_page.hpp"
#include "plot.hpp"
#include "report_text.hpp"

namespace ggxapp {

namespace {

// `p` as planned (a method or a user sampler, in a precision) with each job, and the guards' cost
// and the other sequences side by side.
void add_tasks_of(const BenchPlan& plan, const ggxcl::SampleParams& p, BenchDevice& device,
                  std::vector<BenchTask>& tasks)
{
    for (BenchJob job : plan.jobs) {
        if (!device.jobs->runs(job) || (job == BenchJob::world && p.method == ggxcl::Method::user))
            continue;  // a user sampler works in tangent space
        tasks.push_back({job, p, &device});
        if (p.precision == ggxcl::Precision::precise && job == BenchJob::write && p.method != ggxcl::Method::user) {
            ggxcl::SampleParams unguarded = p;  // the guards' cost, side by side
            unguarded.guards = false;
            tasks.push_back({BenchJob::write, unguarded, &device});
        }
        if (job == BenchJob::write || job == BenchJob::furnace)
            for (const ggxcl::SampleParams& other : other_sequences(plan, p))
                tasks.push_back({job, other, &device});
    }
}

// With --eta, every method but bounded as a dielectric: o + pdf_o written (beside the conductor
// writing the same) and the fused furnace (beside the conductor's furnace task), philox.
void add_dielectric_tasks(const BenchPlan& plan, const ggxcl::SampleParams& conductor, BenchDevice& device,
                          std::vector<BenchTask>& tasks)
{
    if (plan.settings.eta == 0.0f || !ggxcl::method_traits(conductor.method).dielectric)
        return;
    ggxcl::SampleParams dielectric = conductor;
    dielectric.eta = plan.settings.eta;
    dielectric.transport = plan.transport;
    if (plan.plans(BenchJob::write)) {
        tasks.push_back({BenchJob::write_o, conductor, &device});
        tasks.push_back({BenchJob::write_o, dielectric, &device});
    }
    if (plan.plans(BenchJob::furnace))
        tasks.push_back({BenchJob::furnace, dielectric, &device});
}

// A device's tasks: every method x precision x job, then the user samplers that run on it, then the
// dielectric's, and the write job's ceiling where the device has it.
void add_device_tasks(const BenchPlan& plan, BenchDevice& device, std::vector<BenchTask>& tasks)
{
    std::vector<ggxcl::SampleParams> samplers;
    for (ggxcl::Precision precision : plan.precisions)
        for (ggxcl::Method method : plan.methods) {
            samplers.push_back(plan.base);
            samplers.back().method = method;
            samplers.back().precision = precision;
        }
    for (const BenchUserSampler& user : plan.users)
        for (ggxcl::Precision precision : plan.precisions)
            if (runs_on(*user.sampler, *device.backend)) {
                samplers.push_back(plan.base);
                samplers.back().method = ggxcl::Method::user;
                samplers.back().user_sampler = user.sampler;
                samplers.back().precision = precision;
            }
    for (const ggxcl::SampleParams& p : samplers)
        add_tasks_of(plan, p, device, tasks);
    for (const ggxcl::SampleParams& p : samplers)
        if (p.method != ggxcl::Method::user)
            add_dielectric_tasks(plan, p, device, tasks);
    if (plan.plans(BenchJob::write) && device.jobs->runs(BenchJob::store))
        tasks.push_back({BenchJob::store, plan.base, &device});
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
void add_accuracy(const BenchTask& task, const BenchReport& report, const std::vector<BenchUserSampler>& plan_users,
                  ExactValues& exact, BenchRow& row)
{
    ggxcl::Backend& backend = *task.device->backend;
    const ggxcl::SampleParams& p = task.params;
    if (p.eta != 0.0f) {
        if (task.job == BenchJob::furnace) {
            if (!exact.dielectric)
                exact.dielectric = dielectric_exact(p);
            row.dielectric = dielectric_accuracy(backend, p, *exact.dielectric);
        }
        return;
    }
    const bool user = p.method == ggxcl::Method::user;
    ggxcl::Method reference = p.method;
    if (task.job == BenchJob::write && user && p.sequence == ggxcl::Sequence::philox)
        row.pdf_disagreement = pdf_disagreement(backend, p);
    if (task.job == BenchJob::write && (!user || reproduced_method(plan_users, p, reference))) {
        row.has_error = true;
        row.error = numerical_error(backend, p, reference, p.precision, p.sequence);
    }
    if (task.job == BenchJob::furnace && p.sequence == ggxcl::Sequence::philox) {
        SceneVariance scene = albedo_scene_variance(backend, p, p.precision, report.scene_size, report.samples_per_cell);
        row.variance = scene.variance;
        row.mean_albedo = scene.mean_albedo;
    }
    if (task.job == BenchJob::furnace && p.precision == ggxcl::Precision::precise) {
        if (exact.albedo_table.empty())
            exact.albedo_table = albedo_table(report.scene_size);
        row.rmse_measured = albedo_table_rmse(backend, p, p.precision, p.sequence, report.scene_size,
                                              samples_at_budget(row, report), report.rmse_streams, exact.albedo_table);
    }
}

BenchRow device_row(const BenchTask& task, Timing timing)
{
    const ggxcl::SampleParams& p = task.params;
    BenchRow row = task.job == BenchJob::store ? row_of("all", "store-only", "write", timing)
                   : row_of(ggxcl::sampler_name(p),
                            std::string(ggxcl::precision_name(p.precision)) + (p.guards ? "" : "-unguarded"),
                            job_name(task.job), timing);
    row.api = task.device->backend->api_label();
    if (task.job == BenchJob::store)
        return row;
    row.sequence = std::string(ggxcl::sequence_name(p.sequence));
    row.eta = p.eta;
    if (p.eta != 0.0f)
        row.transport = std::string(ggxcl::transport_name(p.transport));
    return row;
}

void measure_devices(std::vector<BenchDevice>& devices, const BenchPlan& plan, const BenchCommand& cmd,
                     BenchReport& report)
{
    std::vector<BenchTask> tasks;
    for (BenchDevice& device : devices)
        add_device_tasks(plan, device, tasks);
    std::cerr << "timing " << tasks.size() << " device rows, " << report.repeats << " interleaved rounds\n";
    const std::vector<Timing> timings = time_interleaved(tasks, report.repeats);
    for (const BenchDevice& device : devices) {
        report.devices.push_back({device.backend->api_label(), device.label(), device.clock});
        if (device.clock != profiled_clock)
            std::cerr << device.label() << ": rows timed by wall clock: " << device.clock << "\n";
    }
    ExactValues exact;
    if (!cmd.no_accuracy)
        std::cerr << "measuring the accuracy columns\n";
    for (std::size_t t = 0; t < tasks.size(); ++t) {
        BenchRow row = device_row(tasks[t], timings[t]);
        if (!cmd.no_accuracy && tasks[t].params.guards && tasks[t].job != BenchJob::store)  // unguarded: speed only
            add_accuracy(tasks[t], report, plan.users, exact, row);
        report.rows.push_back(row);
    }
}

// The native rows; their albedo variance is the first device's precise one for the same method (the
// same samples, drawn from the same uniforms).  All or none: they join the report only once the
// vectorized loop is timed too.
void measure_native(const BenchPlan& plan, BenchReport& report)
{
    std::cerr << "timing the native C++ baseline (ggx-native)\n";
    NativeSetup setup{report.native_count, report.threads, report.repeats, plan.base.alpha_x, plan.base.view};
    std::vector<BenchRow> rows;
    for (ggxcl::Method method : plan.methods) {
        const std::string name(ggxcl::method_name(method));
        for (BenchJob job : plan.jobs) {
            if (job == BenchJob::per_sample)  // the native baseline has no such job
                continue;
            BenchRow row = row_of(name, "native", job_name(job), native_timing(method, job, setup));
            row.api = "native";
            if (job == BenchJob::write) {
                row.has_error = true;
                row.error = native_numerical_error(method);
            }
            for (const BenchRow& device : report.rows)
                if (job == BenchJob::furnace && device.api == report.devices.front().api && device.method == name &&
                    device.precision == "precise" && device.job == "furnace" && device.sequence == "philox" &&
                    device.eta == 0.0f)
                    row.variance = device.variance, row.mean_albedo = device.mean_albedo;
            std::cerr << "  " << name << " native " << job_name(job) << ": " << row.timing.median << " ns\n";
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

// The charts of each device: PREFIX-speed-error.png and PREFIX-speed-rmse.png, with several devices
// PREFIX-API-speed-*.png; paths as written (made relative to a page by the caller).
std::vector<ChartFiles> write_charts(const BenchCommand& cmd, const BenchReport& report)
{
    std::vector<ChartFiles> charts;
    const std::string prefix = charts_prefix(cmd.charts, cmd.html);
    if (prefix.empty())
        return charts;
    for (const BenchDeviceNote& device : report.devices) {
        std::string name = prefix;
        if (report.devices.size() > 1)
            name += "-" + device.api.substr(0, device.api.find(' '));
        ChartFiles files{name + "-speed-error.png", name + "-speed-rmse.png"};
        const std::string csv_path = name + ".plot.csv";
        write_text_file(csv_path, bench_csv(device_report(report, device.api), false));
        run_plot_script("plot_bench.py", {csv_path, files.speed_error, files.speed_rmse, device.label});
        std::filesystem::remove(csv_path);
        charts.push_back(files);
    }
    return charts;
}

void write_outputs(const BenchCommand& cmd, const BenchReport& report)
{
    if (!cmd.csv.empty())
        write_text_file(cmd.csv, bench_csv(report));
    const std::vector<ChartFiles> charts = write_charts(cmd, report);
    // The report with its chart links relative to where it goes.
    const auto report_for = [&](const std::string& page) {
        std::vector<ChartFiles> linked = charts;
        for (ChartFiles& c : linked)
            c = {relative_to(c.speed_error, page), relative_to(c.speed_rmse, page)};
        return bench_markdown(report, linked);
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
    std::vector<BenchDevice> devices;
    const ggxcl::benchmark::JobInputs inputs = random_job_inputs(report.count);
    for (const ApiChoice& choice : plan.apis)
        devices.push_back(open_bench_device(choice, report.count, inputs));
    measure_devices(devices, plan, cmd, report);
    if (!cmd.no_native)
        measure_native_if_available(plan, report);
    if (!cmd.no_startup) {
        std::cerr << "timing start-up, enqueue and whole commands\n";
        const std::vector<std::string> device_args = plan.apis.front().arguments();
        report.startup = measure_startup(device_args, 5);
        report.enqueue = measure_enqueue(plan.apis, plan.base);
        // Twice the device runs' count (2^25 by default): a process's fixed costs weigh as in a dataset run.
        report.apps = measure_apps(device_args, 2 * plan.settings.count);
    }
    write_outputs(cmd, report);
}

// The speed runs: every method in every precision mode, and with --eta every method but bounded
// as a dielectric.
std::vector<Batch> timed_batches(const BenchPlan& plan)
{
    std::vector<Batch> batches;
    for (ggxcl::Precision precision : plan.precisions)
        for (ggxcl::Method method : plan.methods) {
            ggxcl::SampleParams p = plan.base;
            p.method = method;
            p.precision = precision;
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
    cmd->add_option("--alpha", s->alpha, "GGX roughness of the speed runs (one value)");
    cmd->add_option("--theta", s->theta, "view polar angle of the speed runs, degrees, 0..89");
    cmd->add_option("--device", s->device, "device index or name part (see `ggx devices`; vulkan:NAME for Vulkan)");
    cmd->add_option("--methods", s->methods, "comma-separated methods, or all");
    cmd->add_option("--precisions", s->precisions, "comma-separated precision modes");
    cmd->add_option("--sequences", s->sequences, "sequences of uniforms timed in precise mode (write and furnace "
                                                 "jobs): philox (always), sobol");
    cmd->add_option("--jobs", s->jobs, "comma-separated jobs: write (m + pdf_m), furnace (fused estimator), "
                                       "world (world-space o), per-sample (a view and alpha per sample read)");
    cmd->add_option("-n,--count", s->count, "samples per timed device run");
    cmd->add_option("--native-count", s->native_count, "samples per timed native run");
    cmd->add_option("--repeats", s->repeats, "timed runs per row, 5..101 (median reported)");
    cmd->add_option("--threads", s->threads, "threads of the native baseline");
    cmd->add_option("--scene", s->scene, "size of the albedo table (views x roughnesses)");
    cmd->add_option("--cell-samples", s->cell_samples, "samples per cell of the albedo table");
    cmd->add_option("--budget-ms", s->budget_ms, "time budget of the whole table for the RMSE column");
    cmd->add_option("--eta", s->eta, "a rough dielectric's relative index (e.g. 1.5): its write (o + pdf_o) and "
                                     "furnace rows beside the conductor's, every method but bounded; 0: none");
    cmd->add_option("--transport", s->transport, "the dielectric rows' transport: radiance or importance");
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
    api->api_option->description("opencl, vulkan, or opencl,vulkan: the APIs whose devices are timed, in the same "
                                 "rounds (with both, --device chooses OpenCL's device, or with its vulkan: prefix "
                                 "Vulkan's; the other is its default)");
    return [cmd, s, api]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        const BenchPlan plan = plan_bench(*s, api->choose_list(s->device, s->user.files));
        return Work{[s, plan] { run_bench(*s, plan); }, timed_batches(plan)};
    };
}

} // namespace ggxapp
