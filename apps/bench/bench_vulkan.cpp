// bench_vulkan.cpp - `ggx bench --api vulkan` (bench_vulkan.hpp): the jobs
// timed on both APIs and the accuracy on Vulkan (the report and CSV:
// bench_vulkan_report.cpp).
#include "bench_vulkan.hpp"

#include <iostream>

#include "cli_values.hpp"
#include "commands.hpp"
#include "report_text.hpp"

namespace ggxapp {

namespace {

constexpr std::uint64_t bench_seed = 1;

struct ApiTask {
    std::string job;
    ggxcl::SampleParams params;
    const BenchUserSampler* user = nullptr;  // a user sampler's task: Vulkan alone
};

std::vector<ApiTask> api_tasks(const BenchPlan& plan, const std::vector<std::string>& jobs)
{
    std::vector<ApiTask> tasks;
    for (const std::string& mode : plan.precisions) {
        for (const std::string& name : plan.methods)
            for (const std::string& job : jobs) {
                ggxcl::SampleParams p = plan.base;
                p.method = ggxcl::parse_method(name);
                p.precision = ggxcl::parse_precision(mode);
                tasks.push_back({job, p});
                for (const ggxcl::SampleParams& other : other_sequences(plan, p))
                    tasks.push_back({job, other});
                if (job == "furnace" && plan.settings.eta != 0.0f && ggxcl::method_traits(p.method).dielectric) {
                    p.eta = plan.settings.eta;
                    p.transport = plan.transport;
                    tasks.push_back({job, p});
                }
            }
        for (const BenchUserSampler& user : plan.users)  // conductors only
            for (const std::string& job : jobs) {
                ggxcl::SampleParams p = plan.base;
                p.method = ggxcl::Method::user;
                p.user_sampler = user.sampler;
                p.precision = ggxcl::parse_precision(mode);
                tasks.push_back({job, p, &user});
                for (const ggxcl::SampleParams& other : other_sequences(plan, p))
                    tasks.push_back({job, other, &user});
            }
    }
    return tasks;
}

// The accuracy of a precise conductor row on the Vulkan device: the write row's numerical
// error on its sequence (a user sampler's where it reproduces a method) and, on philox, a user
// sampler's pdf self-consistency; the furnace row's albedo variance (philox) and the table's
// RMSE at the budget on its sequence, spent at the row's speed.  `exact`: the table's exact
// albedos, computed when first needed.
void add_accuracy(ggxcl::Backend& vulkan, const ApiTask& task, const ApiBenchReport& report,
                  std::vector<double>& exact, ApiBenchRow& row)
{
    const ggxcl::SampleParams& p = task.params;
    if (p.eta != 0.0f || p.precision != ggxcl::Precision::precise)
        return;
    const bool philox = p.sequence == ggxcl::Sequence::philox;
    if (task.job == "write") {
        if (task.user && philox)
            row.pdf_disagreement = pdf_disagreement(vulkan, p);
        if (!task.user || task.user->reproduces) {
            row.has_error = true;
            row.error = numerical_error(vulkan, p, task.user ? task.user->method : p.method, p.precision, p.sequence);
        }
        return;
    }
    if (philox)
        row.variance =
            albedo_scene_variance(vulkan, p, p.precision, report.scene_size, report.samples_per_cell).variance;
    BenchRow timed;  // the budget's arithmetic of the OpenCL report, on the Vulkan timing
    timed.timing = row.vulkan;
    BenchReport budget;
    budget.scene_size = report.scene_size;
    budget.budget_ms = report.budget_ms;
    row.samples_per_cell = samples_at_budget(timed, budget);
    if (exact.empty())
        exact = albedo_table(report.scene_size);
    row.rmse_measured = albedo_table_rmse(vulkan, p, p.precision, p.sequence, report.scene_size, row.samples_per_cell,
                                          report.rmse_streams, exact);
}

// The job of `task` on one back end.
void run_task(ggxcl::Backend& api, const ApiTask& task, std::uint64_t count)
{
    const ggxcl::SampleRange range{bench_seed, 0, count};
    if (task.job == "furnace")
        api.furnace(task.params, range);
    else
        api.generate(task.params, range, {ggxcl::Field::m, ggxcl::Field::pdf_m});
}

} // namespace

std::vector<std::string> vulkan_bench_jobs(const std::vector<std::string>& planned, bool jobs_given)
{
    if (!jobs_given)
        return {"write", "furnace"};
    for (const std::string& job : planned)
        if (job != "write" && job != "furnace")
            throw UsageError("--jobs", job, "write or furnace with --api vulkan");
    return planned;
}

ApiBenchReport measure_api_bench(const BenchPlan& plan, const std::string& vulkan_selector,
                                 ggxcl::ShaderLanguage language, bool accuracy)
{
    ApiBenchReport report;
    report.command = command_line();
    report.date = utc_now();
    report.machine = machine_description();
    report.count = plan.settings.count;
    report.repeats = plan.settings.repeats;
    report.alpha = plan.settings.alpha;
    report.theta = plan.settings.theta;
    report.accuracy = accuracy;
    report.scene_size = plan.settings.scene_size;
    report.samples_per_cell = plan.settings.samples_per_cell;
    report.budget_ms = plan.settings.budget_ms;
    report.rmse_streams = plan.settings.rmse_streams;
    const std::unique_ptr<ggxcl::Backend> vulkan_backend = ggxcl::open_backend(ggxcl::Api::vulkan, vulkan_selector, language);
    ggxcl::Backend& vulkan = *vulkan_backend;
    report.vulkan_device = vulkan.device_name();
    report.language = ggxcl::shader_language_name(language);
    std::unique_ptr<ggxcl::Backend> opencl;
    try {
        opencl = ggxcl::open_backend(ggxcl::Api::opencl);
        report.opencl_device = opencl->device_name();
    } catch (const ggxcl::Error& e) {
        report.opencl_unavailable = e.what();
        std::cerr << "no OpenCL device to compare with (" << e.what() << "): Vulkan alone\n";
    }
    const std::vector<ApiTask> tasks = api_tasks(plan, plan.jobs);
    std::cerr << "warming up " << tasks.size() << " jobs on each API (builds the shaders and kernels)\n";
    for (const ApiTask& task : tasks) {
        run_task(vulkan, task, std::min<std::uint64_t>(report.count, 1u << 16));
        if (opencl && !task.user)
            run_task(*opencl, task, std::min<std::uint64_t>(report.count, 1u << 16));
    }
    std::vector<std::vector<double>> vk_ns(tasks.size()), cl_ns(tasks.size());
    std::cerr << "timing " << tasks.size() << " jobs x 2 APIs, " << report.repeats << " interleaved rounds\n";
    for (int round = 0; round < report.repeats; ++round)
        for (std::size_t t = 0; t < tasks.size(); ++t) {
            vk_ns[t].push_back(wall_ns_per_sample([&] { run_task(vulkan, tasks[t], report.count); }, report.count));
            if (opencl && !tasks[t].user)
                cl_ns[t].push_back(wall_ns_per_sample([&] { run_task(*opencl, tasks[t], report.count); }, report.count));
        }
    if (accuracy)
        std::cerr << "measuring the accuracy columns on the Vulkan device\n";
    std::vector<double> exact;
    for (std::size_t t = 0; t < tasks.size(); ++t) {
        const ggxcl::SampleParams& p = tasks[t].params;
        ApiBenchRow row;
        row.method = ggxcl::sampler_name(p);
        row.precision = ggxcl::precision_name(p.precision);
        row.job = tasks[t].job;
        row.sequence = ggxcl::sequence_name(p.sequence);
        row.eta = p.eta;
        row.vulkan = summarize(vk_ns[t]);
        row.opencl = cl_ns[t].empty() ? Timing{} : summarize(cl_ns[t]);
        row.user = tasks[t].user != nullptr;
        if (accuracy)
            add_accuracy(vulkan, tasks[t], report, exact, row);
        report.rows.push_back(row);
    }
    return report;
}

} // namespace ggxapp
