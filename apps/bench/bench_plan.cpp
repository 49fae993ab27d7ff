// bench_plan.cpp - checking the options of `ggx bench` into its plan.
#include "bench_plan.hpp"

#include <algorithm>
#include <array>

#include "cli_values.hpp"
#include "sample_options.hpp"

namespace ggxapp {

namespace {

// The report's settings, in the order the options are checked.
void plan_settings(const BenchCommand& cmd, BenchReport& report)
{
    report.count = std::uint32_t(parse_count("-n", cmd.count));
    if (report.count > (1u << 30) || parse_count("-n", cmd.count) > (1u << 30))
        throw UsageError("-n", cmd.count, "1 .. 2^30 samples per timed run");
    report.native_count = std::uint32_t(parse_whole(
        "--native-count", std::to_string(parse_count("--native-count", cmd.native_count)), 1, 1u << 28));
    report.repeats = int(parse_whole("--repeats", cmd.repeats, 5, 101));
    report.threads = int(parse_whole("--threads", cmd.threads, 1, 256));
    report.scene_size = int(parse_whole("--scene", cmd.scene, 2, 64));
    report.samples_per_cell = parse_whole(
        "--cell-samples", std::to_string(parse_count("--cell-samples", cmd.cell_samples)), 2, 1ull << 26);
    report.budget_ms = parse_angle("--budget-ms", cmd.budget_ms, 1e-3, 1e6);
}

} // namespace

std::vector<ggxcl::SampleParams> other_sequences(const BenchPlan& plan, const ggxcl::SampleParams& params)
{
    std::vector<ggxcl::SampleParams> others;
    if (params.precision != ggxcl::Precision::precise)
        return others;
    for (ggxcl::Sequence sequence : plan.sequences) {
        others.push_back(params);
        others.back().sequence = sequence;
    }
    return others;
}

bool BenchPlan::plans(BenchJob job) const
{
    return std::find(jobs.begin(), jobs.end(), job) != jobs.end();
}

bool runs_on(const ggxcl::UserSampler& user, const ggxcl::Backend& backend)
{
    return user.shader_language().has_value() == backend.shader_language().has_value();
}

namespace {

// --sampler, --sampler-name and --reproduces (the k-th for the k-th sampler; none: no map).
void plan_user_samplers(const BenchCommand& cmd, const std::vector<ApiChoice>& apis, BenchPlan& plan)
{
    if (cmd.reproduces.size() > cmd.user.files.size())
        throw UsageError("--reproduces", cmd.reproduces.back(), "at most one per --sampler");
    for (const auto& loaded : cmd.user.load(apis)) {
        BenchUserSampler user{loaded};
        const std::size_t k = plan.users.size();
        if (k < cmd.reproduces.size() && cmd.reproduces[k] != "none") {
            user.method = parsed_option("--reproduces", cmd.reproduces[k], "none or one of " + ggxcl::method_list(),
                                        ggxcl::parse_method);
            user.reproduces = true;
        }
        plan.users.push_back(user);
    }
}

} // namespace

BenchPlan plan_bench(const BenchCommand& cmd, const std::vector<ApiChoice>& apis)
{
    BenchPlan plan;
    plan.apis = apis;
    for (const std::string& name : parse_name_list("--methods", cmd.methods, method_names()))
        plan.methods.push_back(ggxcl::parse_method(name));
    for (const std::string& name : parse_name_list("--precisions", cmd.precisions, {"precise", "relaxed"}))
        plan.precisions.push_back(ggxcl::parse_precision(name));
    for (const std::string& name : parse_name_list("--jobs", cmd.jobs, {"write", "furnace", "world", "per-sample"}))
        for (BenchJob job : all_bench_jobs)
            if (job_name(job) == name)
                plan.jobs.push_back(job);
    for (const std::string& name : parse_name_list("--sequences", cmd.sequences, {"philox", "sobol"}))
        if (name != "philox")  // always timed
            plan.sequences.push_back(ggxcl::parse_sequence(name));
    plan_settings(cmd, plan.settings);
    std::array<float, 2> alpha = parse_alpha("--alpha", cmd.alpha);
    if (alpha[0] != alpha[1])
        throw UsageError("--alpha", cmd.alpha, "one value (the bench includes caps-iso and world space, which are isotropic)");
    plan.settings.alpha = alpha[0];
    plan.settings.theta = parse_angle("--theta", cmd.theta, 0.0, 89.0);
    plan.base.alpha_x = plan.base.alpha_y = alpha[0];
    in_option_terms({{"alpha", {"--alpha", cmd.alpha}}}, [&] { ggxcl::validate(plan.base); });
    plan.base.view = ggxcl::view_from_angles(plan.settings.theta, 0.0);
    plan.settings.eta = parse_eta("--eta", cmd.eta);
    plan.transport = parse_transport_option("--transport", cmd.transport);
    plan.settings.transport = std::string(ggxcl::transport_name(plan.transport));
    plan_user_samplers(cmd, apis, plan);
    return plan;
}

} // namespace ggxapp
