// cmd_demo.cpp - `ggx demo`: the README's main job, samples of every method
// for one configuration written into a folder, one line per method.
#include <filesystem>
#include <iostream>

#include "cli_values.hpp"
#include "commands.hpp"
#include "sample_job.hpp"
#include "sample_options.hpp"

namespace ggxapp {

namespace {
struct DemoCommand {
    SampleOptions options;
    std::string count = "1e5", out = "ggx-demo";
};
} // namespace

Action add_demo_command(CLI::App& app)
{
    auto state = std::make_shared<DemoCommand>();
    CLI::App* cmd = app.add_subcommand("demo", "Write samples of every method for one configuration into a folder");
    state->options.add_view_options(*cmd);
    cmd->add_option("-n,--count", state->count, "samples per method")->capture_default_str();
    cmd->add_option("--out", state->out, "output folder")->capture_default_str();
    return [cmd, state] {
        if (!*cmd)
            return;
        std::uint64_t count = parse_count("-n", state->count);
        std::vector<SampleJob> jobs;
        for (ggxcl::Method method : ggxcl::all_methods) {
            SampleJob job;
            SampleOptions options = state->options;
            if (method == ggxcl::Method::caps_iso)  // isotropic: the first alpha
                options.alpha = options.alpha.substr(0, options.alpha.find(','));
            job.params = options.params_for(method);
            job.theta_degrees = options.parsed_theta();
            job.phi_degrees = options.parsed_phi();
            job.range = {options.parsed_seed(), 0, count};
            job.fields = {ggxcl::Field::m, ggxcl::Field::o, ggxcl::Field::pdf_o, ggxcl::Field::weight};
            job.out = state->out + "/" + std::string(ggxcl::method_name(method)) + ".npy";
            jobs.push_back(job);
        }
        std::filesystem::create_directories(state->out);
        ggxcl::Sampler sampler(state->options.device);
        std::cout << "device: " << sampler.device_name() << "\n";
        for (const SampleJob& job : jobs) {
            run_sample_job(sampler, job);
            std::cout << ggxcl::method_name(job.params.method) << ": " << job.range.count << " samples in "
                      << job.out << " (columns in " << sidecar_path(job.out) << ")\n";
        }
    };
}

} // namespace ggxapp
