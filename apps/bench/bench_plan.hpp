// bench_plan.hpp - the options of `ggx bench` as typed, and the plan they
// give once checked: the method, precision and job lists, the speed runs'
// parameters (and a dielectric's index and transport) and the report's
// settings (counts, repeats, threads, table size, budget).  Planning touches
// no file and no device.
#pragma once

#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "bench_report.hpp"
#include "sample_options.hpp"

namespace ggxapp {

struct BenchCommand {
    std::string alpha = "0.3", theta = "60", device;
    std::string methods = "all", precisions = "precise,relaxed", jobs = "write,furnace,world,per-sample";
    std::string sequences = "philox,sobol";
    std::string count = "2^24", native_count = "2^22", repeats = "7", threads = "2";
    std::string scene = "16", cell_samples = "2^14", budget_ms = "1";
    std::string eta = "0", transport = "radiance";  // a rough dielectric's rows beside the conductor's (0: none)
    bool no_native = false, no_accuracy = false, no_startup = false;
    std::string csv, charts, markdown, html;
    UserSamplerOptions user;              // --sampler FILE.h (repeatable), --sampler-name
    std::vector<std::string> reproduces;  // --reproduces METHOD|none: the k-th sampler's map, for its error
};

// A user sampler's rows: its file, and the built-in method whose map on the same uniforms it
// reproduces (its numerical error is measured against that method's reference), if any.
struct BenchUserSampler {
    std::shared_ptr<const ggxcl::UserSampler> sampler;
    bool reproduces = false;
    ggxcl::Method method = ggxcl::Method::caps;
};

struct BenchPlan {
    std::vector<std::string> methods, precisions, jobs;
    std::vector<std::string> sequences;  // besides philox: timed in precise mode, write and furnace jobs
    ggxcl::SampleParams base;  // the speed runs' roughness and view
    BenchReport settings;      // count, native_count, repeats, threads, scene_size,
                               // samples_per_cell, budget_ms, alpha, theta, eta, transport
    ggxcl::Transport transport = ggxcl::Transport::radiance;  // the dielectric rows' (settings.eta)
    std::vector<BenchUserSampler> users;  // conductor rows beside the methods' (no world job, no native row)
};

// Throws UsageError naming the first bad option; `api` reads the --sampler files.
BenchPlan plan_bench(const BenchCommand& cmd, const ApiChoice& api);

BenchJob job_named(const std::string& name);

// `params` on each of the plan's sequences besides philox (Sobol), timed side by side with it:
// in precise mode; none in relaxed mode.
std::vector<ggxcl::SampleParams> other_sequences(const BenchPlan& plan, const ggxcl::SampleParams& params);

} // namespace ggxapp
