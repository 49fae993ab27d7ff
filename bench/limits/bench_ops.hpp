// bench_ops.hpp - the operations per sample of the bench's write and furnace
// tasks (guarded, philox, conductors) where the device runs OpenCL C: each task's program as the
// runtime builds it (ggxcl::benchmark::DeviceJobs::program: the embedded source and the exact
// options) compiled to LLVM IR by clang (kernel_ir.hpp), once
// per distinct program, all in parallel, before any timing starts; counted
// per sample (the furnace kernel draws GGX_FURNACE_PER_ITEM samples per
// work-item).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "bench_speed.hpp"
#include "op_counts.hpp"

namespace ggxapp {

// One entry per task, none for the tasks not counted.  Where nothing can be counted (no clang, a
// failed compile), every entry is none and `unavailable` says why.
std::vector<std::optional<OpCounts>> count_task_ops(const std::vector<BenchTask>& tasks, std::string& unavailable);

// Whether a task's operations are counted: write or furnace, guarded, philox, a conductor (the
// limits skip the dielectric rows).
bool counts_ops(const BenchTask& task);

} // namespace ggxapp
