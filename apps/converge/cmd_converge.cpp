// cmd_converge.cpp - `ggx converge`: how fast each method's estimates
// converge with each sequence of uniforms (philox, sobol): RMSE against the
// sample count for integrals the reference knows exactly, the fitted slope,
// and RMSE at equal time with the methods' speeds.  Prints the Markdown
// report; --csv, --charts, --markdown and --html write the data, the PNG
// charts, the report and its page.
#include <filesystem>
#include <iostream>

#include "api_options.hpp"
#include "atomic_file.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "converge_report.hpp"
#include "html_page.hpp"
#include "plot.hpp"
#include "report_text.hpp"

namespace ggxapp {

namespace {

void draw_charts(const std::string& charts, const std::string& csv, const std::string& speeds,
                 const std::string& device)
{
    const std::string csv_path = charts + ".plot.csv", speeds_path = charts + ".speeds.csv";
    write_text_file(csv_path, csv);
    write_text_file(speeds_path, speeds);
    try {
        run_plot_script("plot_converge.py", {csv_path, speeds_path, charts, device});
    } catch (...) {
        std::filesystem::remove(csv_path);
        std::filesystem::remove(speeds_path);
        throw;
    }
    std::filesystem::remove(csv_path);
    std::filesystem::remove(speeds_path);
}

void run_converge(const ConvergeCommand& cmd, const ConvergePlan& plan, const ApiChoice& api)
{
    for (const auto& [path, flag] : {std::pair{cmd.csv, "--csv"}, {cmd.markdown, "--markdown"}, {cmd.charts, "--charts"},
                                     {cmd.html, "--html"}})
        if (!path.empty())
            check_writable_folder(flag, path);
    std::vector<ConvergeSpeed> speeds;
    std::vector<ConvergeCurve> curves;
    std::string device;
    {
        const std::unique_ptr<ggxcl::Backend> sampler = api.open();
        device = sampler->device_label();
        std::cerr << "converge: " << plan.methods.size() * plan.sequences.size() * plan.configs.size() << " cells of "
                  << plan.randomizations << " streams of 2^" << plan.max_exponent << " samples on " << device << "\n";
        speeds = measure_speeds(*sampler, plan);
        curves = measure_convergence(*sampler, plan);
    }
    const std::string csv = converge_csv(curves, plan.randomizations);
    if (!cmd.csv.empty())
        write_text_file(cmd.csv, csv);
    ConvergeReportInfo info{command_line(), utc_now(), device, "", plan.randomizations};
    const std::string charts = charts_prefix(cmd.charts, cmd.html);
    if (!charts.empty())
        draw_charts(charts, csv, speeds_csv(speeds), info.device);
    // The report with its chart links relative to where it goes.
    const auto report_for = [&](const std::string& page) {
        info.charts_prefix = charts.empty() ? "" : relative_to(charts, page);
        return converge_markdown(info, plan, curves, speeds);
    };
    const std::string md = report_for(cmd.markdown);
    if (!cmd.markdown.empty())
        write_text_file(cmd.markdown, md);
    if (!cmd.html.empty())
        write_markdown_page(cmd.html, report_for(cmd.html));
    std::cout << md;
}

// The streams the command draws, for tests and fuzz/fuzz_cli.
std::vector<Batch> converge_batches(const ConvergePlan& plan)
{
    std::vector<Batch> batches;
    for (const SamplerChoice& method : plan.methods)
        for (ggxcl::Sequence sequence : plan.sequences)
            for (const ConvergeConfig& config : plan.configs)
                batches.push_back({converge_params(method, sequence, config, plan.precision),
                                   {plan.seed, 0, std::uint64_t(1) << plan.max_exponent}});
    return batches;
}

} // namespace

Prepare add_converge_command(CLI::App& app)
{
    auto s = std::make_shared<ConvergeCommand>();
    CLI::App* cmd = app.add_subcommand("converge", "Error against sample count of every method's estimates with "
                                                   "independent (philox) and Sobol uniforms");
    cmd->add_option("--methods", s->methods, "comma-separated methods, or all");
    s->user.add_to(*cmd);
    cmd->add_option("--sequences", s->sequences, "comma-separated sequences: philox, sobol");
    cmd->add_option("--integrands", s->integrands, "comma-separated: albedo (L = 1), lobe (max(0, o.l)^16 about the "
                                                   "mirror direction), disk (a 10-degree disk light)");
    cmd->add_option("--alphas", s->alphas, "comma-separated roughnesses, 0.01..2");
    cmd->add_option("--thetas", s->thetas, "comma-separated view angles in degrees, 0..89");
    cmd->add_option("--min-n", s->min_n, "smallest sample count, a power of two");
    cmd->add_option("--max-n", s->max_n, "largest sample count, a power of two up to 2^24");
    cmd->add_option("--randomizations", s->randomizations, "independent streams (seeds) per point, 4..4096");
    cmd->add_option("--seed", s->seed, "seed of the first stream");
    cmd->add_option("--precision", s->precision, "precise or relaxed");
    cmd->add_option("--device", s->device, "device index or name part (see `ggx devices`)");
    cmd->add_option("--speed-n", s->speed_n, "samples per timed launch of the speed runs");
    cmd->add_flag("--no-speed", s->no_speed, "skip the speed runs (and the chart at equal time)");
    cmd->add_option("--csv", s->csv, "write every point of every curve to this CSV file");
    cmd->add_option("--charts", s->charts, "write PREFIX-<integrand>.png and PREFIX-time.png");
    cmd->add_option("--markdown", s->markdown, "write the report to this Markdown file");
    cmd->add_option("--html", s->html, "write the report as a web page (with its charts; beside it unless --charts)");
    auto api_options = std::make_shared<ApiOptions>();
    api_options->add_to(*cmd);
    return [cmd, s, api_options]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        const ApiChoice api = api_options->choose(s->device, s->user.files);
        ConvergePlan plan = plan_convergence(*s, api);
        return Work{[s, plan, api] { run_converge(*s, plan, api); }, converge_batches(plan)};
    };
}

} // namespace ggxapp
