// cmd_histogram.cpp - `ggx histogram`: bin a method's reflected directions
// on the device and test them against its pdf (chi-square); `--check ALPHA`
// makes the exit status 1 when p < ALPHA.  A user sampler (--sampler) gets
// every check of user_checks.hpp and user_fit_checks.hpp, and --check fails
// on any that fails.
#include <iostream>

#include "api_options.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "histogram_job.hpp"
#include "sample_options.hpp"

namespace ggxapp {

namespace {

struct HistogramCommand {
    SampleOptions options;
    ApiOptions api_options;
    std::string count = "1e6", first = "0", bins_z = "32", bins_phi = "64", check, against, out, of = "o";
    bool no_png = false;

    // Every option checked; the --out folder is checked by run_histogram.
    HistogramJob job(const ApiChoice& api) const
    {
        HistogramJob job;
        job.params = options.parsed_params(api);
        job.against = job.params.method;
        if (job.params.method == ggxcl::Method::user && !against.empty())
            throw UsageError("--against", against, "no --against with --sampler: its own pdf and the distribution "
                                                   "it claims are both tested");
        if (!against.empty())
            job.against = parse_method_option("--against", against);
        job.theta_degrees = options.parsed_theta();
        job.phi_degrees = options.parsed_phi();
        job.range = options.parsed_range(first, count);
        job.bins_z = int(parse_whole("--bins-z", bins_z, 1, 512));
        job.bins_phi = int(parse_whole("--bins-phi", bins_phi, 1, 1024));
        if (job.params.method == ggxcl::Method::user && job.bins_z % 2 != 0)
            throw UsageError("--bins-z", bins_z, "an even number with --sampler, so that the horizon is a bin edge "
                                                 "(its samples below the horizon with weight 0 are discarded)");
        job.prefix = out;
        job.png = !no_png;
        if (of != "o" && of != "m")
            throw UsageError("--of", of, "o (the reflected direction) or m (the microfacet normal)");
        job.direction = of == "m" ? ggxcl::Field::m : ggxcl::Field::o;
        return job;
    }
};

// The job on the API chosen, the expectation computed while the device opens.
HistogramResult run_on_device(const HistogramJob& job, const ApiChoice& api)
{
    std::future<std::vector<double>> expectation = start_expectation(job);
    const std::unique_ptr<ggxcl::Backend> device = api.open();
    return run_histogram_job(*device, job, std::move(expectation));
}

// `level`: the --check significance level, 0 when none was given.
void run_histogram(const HistogramCommand& command, const HistogramJob& job, const ApiChoice& api, double level)
{
    check_writable_folder("--out", job.prefix);
    HistogramResult result = run_on_device(job, api);
    std::cout << job.prefix << ": chi-square " << result.chi_square << " on " << result.dof << " dof, p = "
              << result.p_value << (result.png.empty() ? "" : ", figure " + result.png) << "\n";
    std::string failed;
    for (const HistogramCheck& check : result.checks) {
        std::cout << "  " << (check.passed ? "pass" : "FAIL") << "  " << check.summary << "\n";
        failed += check.passed ? "" : (failed.empty() ? "" : "; ") + check.name;
    }
    if (level > 0.0 && !failed.empty())
        throw CheckFailed(ggxcl::sampler_name(job.params) + " failed: " + failed);
    if (level > 0.0 && result.p_value < level)
        throw CheckFailed("p = " + std::to_string(result.p_value) + " is below --check " + command.check);
}

} // namespace

Prepare add_histogram_command(CLI::App& app)
{
    auto state = std::make_shared<HistogramCommand>();
    CLI::App* cmd = app.add_subcommand("histogram", "Bin o (or m) on the device and chi-square test it against the pdf");
    state->options.add_method_options(*cmd);
    state->options.add_view_options(*cmd);
    state->api_options.add_to(*cmd);
    cmd->add_option("-n,--count", state->count, "number of samples: 1000, 1e9 or 2^30");
    cmd->add_option("--first", state->first, "index of the first sample");
    cmd->add_option("--bins-z", state->bins_z, "bins over cos theta in [-1, 1]");
    cmd->add_option("--bins-phi", state->bins_phi, "bins over phi in [0, 360)");
    cmd->add_option("--of", state->of, "what to bin: o (reflected direction) or m (microfacet normal; with --sampler, its density "
                    "4 |i.m| pdf_o)");
    cmd->add_option("--against", state->against, "test against this method's pdf instead (a negative control)");
    cmd->add_option("--check", state->check, "exit with status 1 when p < ALPHA (0 < ALPHA < 1)");
    cmd->add_flag("--no-png", state->no_png, "skip the figure (no Python needed)");
    cmd->add_option("--out", state->out,
                    "path prefix of PREFIX.observed.npy, .expected.npy, .json, .png; required");
    return [cmd, state]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        double level = state->check.empty() ? 0.0 : parse_level("--check", state->check);
        const ApiChoice api = state->api_options.choose(state->options.device, {state->options.sampler});
        HistogramJob job = state->job(api);
        if (level > 0.0)
            job.level = level;
        if (state->out.empty())  // what is missing, once every value given has been checked
            throw UsageError("--out is required: a path prefix such as results/caps");
        return Work{[state, job, api, level] { run_histogram(*state, job, api, level); }, {{job.params, job.range}}};
    };
}

} // namespace ggxapp
