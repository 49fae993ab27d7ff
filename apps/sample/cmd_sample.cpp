// cmd_sample.cpp - `ggx sample`: samples of one method into a .npy, .csv or
// .ply with a JSON sidecar, on one device or split across several, or one
// shard of such a job (--shard, see shard_option.hpp).
#include <iostream>
#include <memory>
#include <sstream>

#include "api_options.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "sample_job.hpp"
#include "sample_options.hpp"
#include "shard_option.hpp"
#include "uniforms_file.hpp"

namespace ggxapp {

namespace {

// A checked job and, with --shard, what the summary says of the shard.
struct PreparedSample {
    SampleJob job;
    ApiChoice api;
    std::string shard_note;     // "shard 1/3 (from ...): samples [a, b) of [c, d)", else empty
    std::string shard_warning;  // a doubt about the launcher's environment, else empty
};

struct SampleCommand {
    SampleOptions options;
    ApiOptions api_options;
    std::string count, first = "0", fields = "m,o,pdf_m,pdf_o,weight", out, devices, uniforms, shard;
    bool fields_given = false, all_devices = false, sequence_given = false, shard_given = false;

    bool split() const { return all_devices || !devices.empty(); }

    // One sampler per device of --devices / --all-devices.
    std::vector<std::unique_ptr<ggxcl::Sampler>> split_samplers() const
    {
        std::vector<std::unique_ptr<ggxcl::Sampler>> list;
        if (all_devices) {
            for (const ggxcl::DeviceInfo& d : ggxcl::list_devices())
                list.push_back(std::make_unique<ggxcl::Sampler>(d));
            return list;
        }
        std::stringstream items(devices);
        std::string item;
        while (std::getline(items, item, ','))
            list.push_back(std::make_unique<ggxcl::Sampler>(ggxcl::select_device(item)));
        return list;
    }

    // Every option checked; the --out folder is checked by run_sample.
    PreparedSample prepare() const
    {
        const ApiChoice chosen = api();
        PreparedSample prepared{job(chosen), chosen, "", ""};
        if (shard_given)
            take_shard(prepared);
        else if (out.find("{shard}") != std::string::npos)
            throw UsageError("--out", out, "a path without {shard}, which only --shard replaces");
        return prepared;
    }

    // Narrows the whole job to the shard --shard names: its range, its rows
    // of --uniforms and its file.
    void take_shard(PreparedSample& prepared) const
    {
        Shard part = parse_shard(shard);
        SampleJob& job = prepared.job;
        const ggxcl::SampleRange whole = job.range;
        job.range = shard_range(whole, part);
        job.out = shard_out_path(out, part);
        const auto skipped = std::ptrdiff_t(job.range.first - whole.first), kept = std::ptrdiff_t(job.range.count);
        if (!job.per_sample.uniforms.empty()) {
            auto rows = job.per_sample.uniforms.begin() + skipped;
            job.per_sample.uniforms.assign(rows, rows + kept);
        }
        if (!job.per_sample.lobe_uniforms.empty()) {
            auto rows = job.per_sample.lobe_uniforms.begin() + skipped;
            job.per_sample.lobe_uniforms.assign(rows, rows + kept);
        }
        prepared.shard_note = describe_shard(part, job.range, whole);
        prepared.shard_warning = part.warning;
    }

    // The API of --api / --device / --sampler, and what Vulkan cannot do yet.
    ApiChoice api() const
    {
        const ApiChoice choice = api_options.choose(options.device, {options.sampler});
        if (choice.api == ggxcl::Api::vulkan && (all_devices || !devices.empty()))
            throw UsageError(all_devices ? "--all-devices" : "--devices", all_devices ? "" : devices,
                             "one device with --api vulkan: give it with --device");
        return choice;
    }

    // The whole job (before --shard).
    SampleJob job(const ApiChoice& api) const
    {
        SampleJob job;
        job.params = options.parsed_params(api);
        job.theta_degrees = options.parsed_theta();
        job.phi_degrees = options.parsed_phi();
        job.fields = parsed_option("--fields", fields, "a comma-separated list of distinct " + ggxcl::field_list(),
                                   ggxcl::parse_field_list);
        if (!out.empty())
            job.format = format_of("--out", out);
        if (!uniforms.empty())
            read_uniforms_into(job);
        if (!count.empty() || !uniforms.empty())
            job.range =
                options.parsed_range(first, count.empty() ? std::to_string(job.per_sample.uniforms.size()) : count);
        if (!uniforms.empty() && job.range.count != job.per_sample.uniforms.size())
            throw UsageError("-n", count, std::to_string(job.per_sample.uniforms.size()) + ", the rows of --uniforms");
        // What is missing, once every value given has been checked.
        if (count.empty() && uniforms.empty())
            throw UsageError("-n is required (or --uniforms, whose rows give the count)");
        if (out.empty())
            throw UsageError("--out is required: the .npy, .csv or .ply file to write");
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
        read_uniforms(uniforms, job.params.eta != 0.0f, job.per_sample);
        job.uniforms_file = uniforms;
    }
};

void run_sample(const SampleCommand& command, const PreparedSample& prepared)
{
    const SampleJob& job = prepared.job;
    if (!prepared.shard_warning.empty())
        std::cerr << "ggx: warning: " << prepared.shard_warning << "\n";
    check_writable_folder("--out", job.out);
    if (command.split()) {
        std::vector<std::unique_ptr<ggxcl::Sampler>> owned = command.split_samplers();
        std::vector<ggxcl::Sampler*> samplers;
        for (auto& s : owned)
            samplers.push_back(s.get());
        run_split_sample_job(samplers, job);
    } else {
        run_sample_job(*prepared.api.open(), job);
    }
    std::cout << job.out << ": " << job.range.count << " samples of " << ggxcl::sampler_name(job.params)
              << (prepared.shard_note.empty() ? "" : ", " + prepared.shard_note) << "\n";
}

// What the prepared job will sample: nothing for an empty shard.
std::vector<Batch> batches_of(const SampleJob& job)
{
    if (job.range.count == 0)
        return {};
    return {{job.params, job.range}};
}

} // namespace

Prepare add_sample_command(CLI::App& app)
{
    auto state = std::make_shared<SampleCommand>();
    CLI::App* cmd = app.add_subcommand("sample", "Write samples of one method to a .npy file with a JSON sidecar");
    state->options.add_method_options(*cmd);
    state->options.add_view_options(*cmd);
    state->api_options.add_to(*cmd);
    cmd->add_option("-n,--count", state->count,
                    "number of samples: 1000, 1e6 or 2^24 (default with --uniforms: its rows); with --shard, of "
                    "the whole job");
    cmd->add_option("--first", state->first, "index of the first sample (with --shard, of the whole job)");
    CLI::Option* shard = cmd->add_option(
        "--shard", state->shard,
        "write only shard R of S of the job: R/S (0 <= R < S; samples [N*R/S, N*(R+1)/S) from --first, and those "
        "rows of --uniforms), or auto: R and S of the launcher (OMPI_COMM_WORLD_RANK/SIZE, PMI_RANK/SIZE, "
        "SLURM_ARRAY_TASK_ID/COUNT less _MIN, SLURM_PROCID/NTASKS); --out must contain {shard}, replaced by R as "
        "0007; a shard may be empty (S > N); join the shards with `ggx merge`");
    CLI::Option* fields = cmd->add_option("--fields", state->fields,
                                          "columns, in order, of m,o,pdf_m,pdf_o,weight,u (.ply: o or m)");
    cmd->add_option("--out", state->out, "output .npy, .csv or .ply (a .json sidecar goes beside it; with "
                                         "--shard it contains {shard}); required");
    cmd->add_option("--devices", state->devices, "split the job across these devices: selectors separated by commas");
    cmd->add_flag("--all-devices", state->all_devices, "split the job across every device of the machine");
    cmd->add_option("--uniforms", state->uniforms,
                    "the uniforms of each sample: a float32 or float64 .npy of shape (N, 2), values in [0, 1)");
    return [cmd, state, fields, shard]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        state->fields_given = fields->count() > 0;
        state->shard_given = shard->count() > 0;
        state->sequence_given = cmd->get_option("--sequence")->count() > 0;
        PreparedSample prepared = state->prepare();
        std::vector<Batch> batches = batches_of(prepared.job);
        return Work{[state, prepared] { run_sample(*state, prepared); }, batches};
    };
}

} // namespace ggxapp
