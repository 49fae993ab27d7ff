// shard_option.hpp - `ggx sample --shard R/S | auto`: which part of a job
// one process samples.  Shard R of S covers the sample indices
// [F + floor(N*R/S), F + floor(N*(R+1)/S)) of the job's -n N from --first
// F.  `auto` takes R and S from the environment the launcher sets, in this
// order: Open MPI (OMPI_COMM_WORLD_RANK, OMPI_COMM_WORLD_SIZE), MPICH and
// Intel MPI (PMI_RANK, PMI_SIZE), a Slurm job array (SLURM_ARRAY_TASK_ID,
// less SLURM_ARRAY_TASK_MIN, over SLURM_ARRAY_TASK_STEP, of
// SLURM_ARRAY_TASK_COUNT) and srun (SLURM_PROCID, SLURM_NTASKS): no MPI
// library is linked, so one binary runs under any launcher.  Bad values
// throw UsageError naming the option or variable, the value and what is
// allowed.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <ggxcl/ggxcl.hpp>

namespace ggxapp {

struct Shard {
    std::uint64_t rank = 0, size = 1;
    std::string source;   // "--shard" or the variables it came from, e.g. "OMPI_COMM_WORLD_RANK/OMPI_COMM_WORLD_SIZE"
    std::string warning;  // a doubt about the environment worth printing, else empty
};

// The value of an environment variable, or nothing when it is not set.
using Environment = std::function<std::optional<std::string>(const std::string& name)>;
std::optional<std::string> process_environment(const std::string& name);

// "R/S" or "auto" (read through `environment`).
Shard parse_shard(const std::string& text, const Environment& environment = process_environment);

// The part of `whole` that `shard` covers; empty (count 0) when S > N and
// the shard gets no index.  Exact for any 64-bit N, R and S.
ggxcl::SampleRange shard_range(const ggxcl::SampleRange& whole, const Shard& shard);

// R zero-padded to 4 digits, or to the digits of S - 1 when more, so that
// the shell's glob lists the shards in order: 7 of 16 -> "0007".
std::string shard_number(const Shard& shard);

// `out` with every "{shard}" replaced by shard_number; throws UsageError
// when `out` has none (every shard would write the same file).
std::string shard_out_path(const std::string& out, const Shard& shard);

// For the summary: "shard 1/3 (from OMPI_COMM_WORLD_RANK/OMPI_COMM_WORLD_SIZE):
// samples [2000, 4000) of [0, 6000)".
std::string describe_shard(const Shard& shard, const ggxcl::SampleRange& part, const ggxcl::SampleRange& whole);

} // namespace ggxapp
