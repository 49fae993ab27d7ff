// bench_plan.hpp - the options of `ggx bench` as typed, and the plan they
// give once checked: the APIs and devices, the methods, precisions, jobs
// and sequences as the library's enums, the speed runs' parameters (and a
// dielectric's index and transport), the user samplers, and the report's
// settings (counts, repeats, threads, table size, budget).  Planning opens
// no device.
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
    std::vector<ApiChoice> apis;  // each API's device, in the report's order
    std::vector<ggxcl::Method> methods;
    std::vector<ggxcl::Precision> precisions;
    std::vector<BenchJob> jobs;
    std::vector<ggxcl::Sequence> sequences;  // besides philox: timed in precise mode, write and furnace jobs
    ggxcl::SampleParams base;  // the speed runs' roughness and view
    BenchReport settings;      // count, native_count, repeats, threads, scene_size,
                               // samples_per_cell, budget_ms, alpha, theta, eta, transport
    ggxcl::Transport transport = ggxcl::Transport::radiance;  // the dielectric rows' (settings.eta)
    std::vector<BenchUserSampler> users;  // conductor rows beside the methods' (no world job, no native row)
    bool plans(BenchJob job) const;
};

// Throws UsageError naming the first bad option; `apis` (ApiOptions::choose_list) read the --sampler
// files: a .glsl or .hlsl file for Vulkan, another for OpenCL where it is planned.
BenchPlan plan_bench(const BenchCommand& cmd, const std::vector<ApiChoice>& apis);

// Whether `user` runs on `backend`: a shader on Vulkan, OpenCL C on OpenCL.
bool runs_on(const ggxcl::UserSampler& user, const ggxcl::Backend& backend);

// `params` on each of the plan's sequences besides philox (Sobol), timed side by side with it:
// in precise mode; none in relaxed mode.
std::vector<ggxcl::SampleParams> other_sequences(const BenchPlan& plan, const ggxcl::SampleParams& params);

} // namespace ggxapp
