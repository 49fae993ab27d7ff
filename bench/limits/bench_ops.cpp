// bench_ops.cpp - the bench tasks' programs through clang, counted per sample.
#include "bench_ops.hpp"

#include <algorithm>
#include <stdexcept>
#include <thread>

#include <ggxcl/benchmark.hpp>
#include <ggxcl/cl/ggx_contract.h>

#include "kernel_ir.hpp"

namespace ggxapp {

bool counts_ops(const BenchTask& task)
{
    return (task.job == BenchJob::write || task.job == BenchJob::furnace) && task.params.guards &&
           task.params.method != ggxcl::Method::user &&  // the limits table holds the built-in methods
           task.params.sequence == ggxcl::Sequence::philox && task.params.eta == 0.0f;
}

std::vector<std::optional<OpCounts>> count_task_ops(const std::vector<BenchTask>& tasks, std::string& unavailable)
{
    std::vector<std::optional<OpCounts>> counts(tasks.size());
    std::vector<std::size_t> counted;
    std::vector<ggxcl::benchmark::ProgramText> programs;
    std::vector<IrRequest> requests;
    for (std::size_t t = 0; t < tasks.size(); ++t) {
        if (!counts_ops(tasks[t]))
            continue;
        // The program the timed runs build, where the device's is OpenCL C.
        std::optional<ggxcl::benchmark::ProgramText> program = tasks[t].device->jobs->program(tasks[t].job, tasks[t].params);
        if (!program)
            continue;
        programs.push_back(*program);
        requests.push_back({ggxcl::kernel_source(programs.back().file), programs.back().options});
        counted.push_back(t);
    }
    const ClangTool clang = counted.empty() ? ClangTool{} : find_clang();
    if (counted.empty() || clang.path.empty()) {
        unavailable = clang.unavailable;
        return counts;
    }
    try {
        const int parallel = int(std::max(1u, std::thread::hardware_concurrency()));
        const std::vector<std::string> ir = compile_to_ir(clang, requests, parallel);
        for (std::size_t k = 0; k < counted.size(); ++k) {
            const double samples = tasks[counted[k]].job == BenchJob::furnace ? GGX_FURNACE_PER_ITEM : 1;
            counts[counted[k]] = count_kernel_ops(ir[k], programs[k].kernel).per(samples);
        }
    } catch (const std::exception& e) {
        unavailable = e.what();
        std::fill(counts.begin(), counts.end(), std::nullopt);
    }
    return counts;
}

} // namespace ggxapp
