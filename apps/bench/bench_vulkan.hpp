// bench_vulkan.hpp - `ggx bench --api vulkan`: the same jobs timed on a
// Vulkan device and on the OpenCL device beside it, in one run, with their
// ratio: which API is faster for each method on this machine.  Jobs:
//   write   - m and pdf_m of the samples into host memory (VulkanSampler::generate,
//             Sampler::generate);
//   furnace - the fused white-furnace estimator (VulkanSampler::furnace,
//             Sampler::furnace), a dielectric's too with --eta.
// In precise mode each runs on philox and on the other --sequences (Sobol).
// Each row is the median of `repeats` wall-clock timings of the whole call,
// both APIs timed back to back in each round after a warm-up that builds
// the shader and the kernel.  User samplers (--sampler FILE.glsl|.hlsl) get
// rows of their own on Vulkan alone.  Unless --no-accuracy, the precise
// conductor rows get accuracy on the Vulkan device, as `ggx bench` on
// OpenCL measures it (bench_accuracy.hpp): the write rows' numerical error
// (a user sampler's with --reproduces) and a user sampler's pdf
// self-consistency, the furnace rows' albedo variance and the albedo
// table's RMSE at equal time.
#pragma once

#include <string>
#include <vector>

#include "bench_plan.hpp"
#include "bench_speed.hpp"

namespace ggxapp {

struct ApiBenchRow {
    std::string method, precision, job;
    std::string sequence;  // of the uniforms: philox, or sobol in precise mode
    float eta = 0;  // a dielectric's furnace (0: the conductor)
    Timing vulkan, opencl;  // ns per sample; opencl.median 0: no OpenCL device, or a user sampler
    double ratio() const { return opencl.median > 0 ? vulkan.median / opencl.median : 0.0; }
    bool user = false;      // a user sampler's row (Vulkan alone)
    // Accuracy on the Vulkan device (precise conductor rows; 0 or -1: not measured).
    bool has_error = false;        // write: numerical error against the reference
    NumericalError error;
    double pdf_disagreement = -1;  // write, user samplers: fraction of pdf_o off their pdf from (i, o)
    double variance = 0;           // furnace: albedo estimator variance per sample over the table
    std::uint64_t samples_per_cell = 0;  // furnace: what the budget buys per cell at this row's speed
    double rmse_measured = 0;      // furnace: the table's RMSE at the budget, measured
};

struct ApiBenchReport {
    std::string command, date, machine;
    std::string vulkan_device, language, opencl_device;  // opencl_device empty: none (opencl_unavailable says why)
    std::string opencl_unavailable;
    std::uint32_t count = 0;
    int repeats = 0;
    double alpha = 0, theta = 0;
    bool accuracy = false;       // the accuracy columns were measured
    int scene_size = 0, rmse_streams = 0;
    std::uint64_t samples_per_cell = 0;  // of the variance's table
    double budget_ms = 0;
    std::vector<ApiBenchRow> rows;
};

// The jobs --api vulkan times: write and furnace; UsageError for others.
std::vector<std::string> vulkan_bench_jobs(const std::vector<std::string>& planned, bool jobs_given);

// Times every method x precision x job of the plan on both APIs, and the
// user samplers' on Vulkan; with `accuracy`, measures the accuracy columns.
ApiBenchReport measure_api_bench(const BenchPlan& plan, const std::string& vulkan_selector,
                                 ggxcl::ShaderLanguage language, bool accuracy);

std::string api_bench_markdown(const ApiBenchReport& report);
std::string api_bench_csv(const ApiBenchReport& report);

} // namespace ggxapp
