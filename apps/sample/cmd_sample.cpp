// cmd_sample.cpp - `ggx sample`: samples of one method into a .npy, .csv or
// .ply with a JSON sidecar, on one device or split across several.
#include <iostream>
#include <memory>
#include <sstream>

#include "cli_values.hpp"
#include "commands.hpp"
#include "sample_job.hpp"
#include "sample_options.hpp"
#include "uniforms_file.hpp"

namespace ggxapp {

namespace {

struct SampleCommand {
    SampleOptions options;
    std::string count, first = "0", fields = "m,o,pdf_m,pdf_o,weight", out, devices, uniforms;
    bool fields_given = false, all_devices = false, sequence_given = false;

    // One sampler per device of --devices / --all-devices, else the one of --device.
    std::vector<std::unique_ptr<ggxcl::Sampler>> samplers() const
    {
        std::vector<std::unique_ptr<ggxcl::Sampler>> list;
        if (all_devices) {
            for (const ggxcl::DeviceInfo& d : ggxcl::list_devices())
                list.push_back(std::make_unique<ggxcl::Sampler>(d));
        } else if (!devices.empty()) {
            std::stringstream items(devices);
            std::string item;
            while (std::getline(items, item, ','))
                list.push_back(std::make_unique<ggxcl::Sampler>(ggxcl::select_device(item)));
        } else {
            list.push_back(std::make_unique<ggxcl::Sampler>(options.device));
        }
        return list;
    }

    // Every option checked; the --out folder is checked by run_sample.
    SampleJob job() const
    {
        SampleJob job;
        job.params = options.params_for(options.parsed_method());
        job.theta_degrees = options.parsed_theta();
        job.phi_degrees = options.parsed_phi();
        if (!uniforms.empty())
            read_uniforms_into(job);
        else if (count.empty())
            throw UsageError("-n is required (or --uniforms, whose rows give the count)");
        job.range = options.parsed_range(first, count.empty() ? std::to_string(job.per_sample.uniforms.size()) : count);
        if (!uniforms.empty() && job.range.count != job.per_sample.uniforms.size())
            throw UsageError("-n", count, std::to_string(job.per_sample.uniforms.size()) + ", the rows of --uniforms");
        try {
            job.fields = ggxcl::parse_field_list(fields);
        } catch (const ggxcl::InvalidArgument&) {
            throw UsageError("--fields", fields, "a comma-separated list of distinct " + ggxcl::field_list());
        }
        job.format = format_of("--out", out);
        if (job.format == Format::ply) {
            try {
                job.fields = ply_fields(fields_given ? job.fields : std::vector<ggxcl::Field>{ggxcl::Field::o});
            } catch (const UsageError&) {
                throw UsageError("--fields", fields, "o or m for a .ply (the direction plotted, colored by its pdf)");
            }
        }
        job.out = out;
        return job;
    }

    // The rows of --uniforms, on one device and with no --sequence.
    void read_uniforms_into(SampleJob& job) const
    {
        if (sequence_given)
            throw UsageError("--sequence", options.sequence, "nothing with --uniforms, which replaces the sequence");
        if (all_devices || !devices.empty())
            throw UsageError("--uniforms", uniforms, "one device: not with --devices or --all-devices");
        job.per_sample.uniforms = read_uniforms(uniforms);
        job.uniforms_file = uniforms;
    }
};

void run_sample(const SampleCommand& command, const SampleJob& job)
{
    check_writable_folder("--out", job.out);
    std::vector<std::unique_ptr<ggxcl::Sampler>> owned = command.samplers();
    std::vector<ggxcl::Sampler*> samplers;
    for (auto& s : owned)
        samplers.push_back(s.get());
    run_sample_job(samplers, job);
    std::cout << job.out << ": " << job.range.count << " samples of " << command.options.method << "\n";
}

} // namespace

Prepare add_sample_command(CLI::App& app)
{
    auto state = std::make_shared<SampleCommand>();
    CLI::App* cmd = app.add_subcommand("sample", "Write samples of one method to a .npy file with a JSON sidecar");
    state->options.add_method_options(*cmd);
    state->options.add_view_options(*cmd);
    cmd->add_option("-n,--count", state->count, "number of samples: 1000, 1e6 or 2^24 (default with --uniforms: its rows)");
    cmd->add_option("--first", state->first, "index of the first sample (for shards)")->capture_default_str();
    CLI::Option* fields = cmd->add_option("--fields", state->fields,
                                          "columns, in order, of m,o,pdf_m,pdf_o,weight,u (.ply: o or m)")
                              ->capture_default_str();
    cmd->add_option("--out", state->out, "output .npy, .csv or .ply (a .json sidecar goes beside it)")->required();
    cmd->add_option("--devices", state->devices, "split the job across these devices: selectors separated by commas");
    cmd->add_flag("--all-devices", state->all_devices, "split the job across every device of the machine");
    cmd->add_option("--uniforms", state->uniforms,
                    "the uniforms of each sample: a float32 or float64 .npy of shape (N, 2), values in [0, 1)");
    return [cmd, state, fields]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        state->fields_given = fields->count() > 0;
        state->sequence_given = cmd->get_option("--sequence")->count() > 0;
        SampleJob job = state->job();
        return Work{[state, job] { run_sample(*state, job); }, {{job.params, job.range}}};
    };
}

} // namespace ggxapp
