// bench_vulkan.hpp - `ggx bench --api vulkan`: the same jobs timed on a
// Vulkan device and on the OpenCL device beside it, in one run, with their
// ratio: which API is faster for each method on this machine.  Jobs:
//   write   - m and pdf_m of the samples into host memory (VulkanSampler::generate,
//             Sampler::generate);
//   furnace - the fused white-furnace estimator (VulkanSampler::furnace,
//             Sampler::furnace), a dielectric's too with --eta.
// Each row is the median of `repeats` wall-clock timings of the whole call,
// both APIs timed back to back in each round after a warm-up that builds
// the shader and the kernel.
#pragma once

#include <string>
#include <vector>

#include "bench_plan.hpp"
#include "bench_speed.hpp"

namespace ggxapp {

struct ApiBenchRow {
    std::string method, precision, job;
    float eta = 0;  // a dielectric's furnace (0: the conductor)
    Timing vulkan, opencl;  // ns per sample; opencl.median 0: no OpenCL device
    double ratio() const { return opencl.median > 0 ? vulkan.median / opencl.median : 0.0; }
};

struct ApiBenchReport {
    std::string command, date, machine;
    std::string vulkan_device, language, opencl_device;  // opencl_device empty: none (opencl_unavailable says why)
    std::string opencl_unavailable;
    std::uint32_t count = 0;
    int repeats = 0;
    double alpha = 0, theta = 0;
    std::vector<ApiBenchRow> rows;
};

// The jobs --api vulkan times: write and furnace; UsageError for others.
std::vector<std::string> vulkan_bench_jobs(const std::vector<std::string>& planned, bool jobs_given);

// Times every method x precision x job of the plan on both APIs.
ApiBenchReport measure_api_bench(const BenchPlan& plan, const std::string& vulkan_selector,
                                 ggxcl::ShaderLanguage language);

std::string api_bench_markdown(const ApiBenchReport& report);
std::string api_bench_csv(const ApiBenchReport& report);

} // namespace ggxapp
