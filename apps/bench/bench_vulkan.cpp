// bench_vulkan.cpp - `ggx bench --api vulkan` (bench_vulkan.hpp): the jobs
// timed on both APIs, their report and CSV.
#include "bench_vulkan.hpp"

#include <iostream>
#include <sstream>

#include "cli_values.hpp"
#include "commands.hpp"
#include "report_text.hpp"

namespace ggxapp {

namespace {

constexpr std::uint64_t bench_seed = 1;

struct ApiTask {
    std::string job;
    ggxcl::SampleParams params;
};

std::vector<ApiTask> api_tasks(const BenchPlan& plan, const std::vector<std::string>& jobs)
{
    std::vector<ApiTask> tasks;
    for (const std::string& mode : plan.precisions)
        for (const std::string& name : plan.methods)
            for (const std::string& job : jobs) {
                ggxcl::SampleParams p = plan.base;
                p.method = ggxcl::parse_method(name);
                p.precision = ggxcl::parse_precision(mode);
                tasks.push_back({job, p});
                if (job == "furnace" && plan.settings.eta != 0.0f && ggxcl::method_traits(p.method).dielectric) {
                    p.eta = plan.settings.eta;
                    p.transport = plan.transport;
                    tasks.push_back({job, p});
                }
            }
    return tasks;
}

// The job of `task` on one API; Api is ggxcl::Sampler or ggxcl::VulkanSampler.
template <typename Api>
void run_task(Api& api, const ApiTask& task, std::uint64_t count)
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
                                 ggxcl::ShaderLanguage language)
{
    ApiBenchReport report;
    report.command = command_line();
    report.date = utc_now();
    report.machine = machine_description();
    report.count = plan.settings.count;
    report.repeats = plan.settings.repeats;
    report.alpha = plan.settings.alpha;
    report.theta = plan.settings.theta;
    ggxcl::VulkanSampler vulkan(vulkan_selector, language);
    report.vulkan_device = vulkan.device_name();
    report.language = ggxcl::shader_language_name(language);
    std::unique_ptr<ggxcl::Sampler> opencl;
    try {
        opencl = std::make_unique<ggxcl::Sampler>();
        report.opencl_device = opencl->device_name();
    } catch (const ggxcl::Error& e) {
        report.opencl_unavailable = e.what();
        std::cerr << "no OpenCL device to compare with (" << e.what() << "): Vulkan alone\n";
    }
    const std::vector<ApiTask> tasks = api_tasks(plan, plan.jobs);
    std::cerr << "warming up " << tasks.size() << " jobs on each API (builds the shaders and kernels)\n";
    for (const ApiTask& task : tasks) {
        run_task(vulkan, task, std::min<std::uint64_t>(report.count, 1u << 16));
        if (opencl)
            run_task(*opencl, task, std::min<std::uint64_t>(report.count, 1u << 16));
    }
    std::vector<std::vector<double>> vk_ns(tasks.size()), cl_ns(tasks.size());
    std::cerr << "timing " << tasks.size() << " jobs x 2 APIs, " << report.repeats << " interleaved rounds\n";
    for (int round = 0; round < report.repeats; ++round)
        for (std::size_t t = 0; t < tasks.size(); ++t) {
            vk_ns[t].push_back(wall_ns_per_sample([&] { run_task(vulkan, tasks[t], report.count); }, report.count));
            if (opencl)
                cl_ns[t].push_back(wall_ns_per_sample([&] { run_task(*opencl, tasks[t], report.count); }, report.count));
        }
    for (std::size_t t = 0; t < tasks.size(); ++t) {
        const ggxcl::SampleParams& p = tasks[t].params;
        ApiBenchRow row{std::string(ggxcl::method_name(p.method)), std::string(ggxcl::precision_name(p.precision)),
                        tasks[t].job, p.eta,
                        summarize(vk_ns[t]), opencl ? summarize(cl_ns[t]) : Timing{}};
        report.rows.push_back(row);
    }
    return report;
}

std::string api_bench_markdown(const ApiBenchReport& r)
{
    std::ostringstream md;
    md << "# Vulkan against OpenCL\n\n"
       << "- Vulkan device: " << r.vulkan_device << ", shaders in " << r.language << "\n"
       << "- OpenCL device: " << (r.opencl_device.empty() ? "none (" + r.opencl_unavailable + ")" : r.opencl_device)
       << "\n- Machine: " << r.machine << "; " << r.date << "\n"
       << "- Command: `" << r.command << "`\n"
       << "- " << r.count << " samples per run, alpha " << r.alpha << ", view " << r.theta
       << " degrees from the normal; the median of " << r.repeats
       << " wall-clock runs of the whole library call (fastest–slowest), both APIs timed back to back in "
          "each round.  write: m and pdf_m into host memory; furnace: the fused white-furnace estimator.\n"
       << "- Vulkan / OpenCL below 1: Vulkan is faster.\n\n"
       << "| method | precision | job | Vulkan ns/sample | OpenCL ns/sample | Vulkan / OpenCL |\n"
       << "|---|---|---|---|---|---|\n";
    const auto timing = [](const Timing& t) {
        return t.median > 0 ? readable_number(t.median) + " (" + readable_number(t.low) + "–" + readable_number(t.high) + ")"
                            : std::string("–");
    };
    for (const ApiBenchRow& row : r.rows)
        md << "| " << row.method << " | " << row.precision << " | " << row.job
           << (row.eta != 0.0f ? " (dielectric, eta " + readable_number(row.eta) + ")" : "") << " | "
           << timing(row.vulkan) << " | " << timing(row.opencl) << " | "
           << (row.ratio() > 0 ? readable_number(row.ratio()) : "–") << " |\n";
    return md.str();
}

std::string api_bench_csv(const ApiBenchReport& r)
{
    std::ostringstream csv;
    csv << "method,precision,job,eta,vulkan_ns,vulkan_low,vulkan_high,opencl_ns,opencl_low,opencl_high,ratio,"
           "vulkan_device,opencl_device\n";
    for (const ApiBenchRow& row : r.rows)
        csv << row.method << "," << row.precision << "," << row.job << "," << row.eta << "," << row.vulkan.median << ","
            << row.vulkan.low << "," << row.vulkan.high << "," << row.opencl.median << "," << row.opencl.low << ","
            << row.opencl.high << "," << row.ratio() << ",\"" << r.vulkan_device << "\",\"" << r.opencl_device
            << "\"\n";
    return csv.str();
}

} // namespace ggxapp
