// shard_option.cpp - parsing `--shard R/S | auto`, the launchers'
// environment variables, and the range and file name of a shard.
#include "shard_option.hpp"

#include <algorithm>
#include <cstdlib>

#include "cli_values.hpp"

namespace ggxapp {

namespace {

const std::string explicit_allowed =
    "a shard R/S with whole numbers 0 <= R < S, or auto (rank and size from mpirun, srun or a Slurm job array)";
const std::string auto_flag = "--shard auto";

// `text` as a whole number of 0 .. 2^64-1 (digits only), else nothing.
std::optional<std::uint64_t> to_uint64(const std::string& text)
{
    try {
        return parse_uint64("", text);
    } catch (const UsageError&) {
        return std::nullopt;
    }
}

std::string assignment(const std::string& name, const std::string& value) { return name + "=" + value; }

// The variable `name` as a whole number >= low; UsageError naming it and its value otherwise.
std::uint64_t variable_number(const std::string& name, const std::string& value, std::uint64_t low)
{
    std::optional<std::uint64_t> number = to_uint64(value);
    if (!number || *number < low)
        throw UsageError(auto_flag, assignment(name, value),
                         "a whole number from " + std::to_string(low) + " to 2^64-1");
    return *number;
}

// The value of a variable that must be set because `because` is.
std::string required_variable(const Environment& environment, const std::string& name, const std::string& because)
{
    std::optional<std::string> value = environment(name);
    if (!value)
        throw UsageError(auto_flag + ": " + because + " is set but " + name + " is not");
    return *value;
}

// A rank and size pair of variables (Open MPI, PMI, srun); the rank is set.
Shard from_rank_and_size(const Environment& environment, const std::string& rank_name, const std::string& size_name)
{
    const std::string rank_text = *environment(rank_name);
    const std::string size_text = required_variable(environment, size_name, rank_name);
    Shard shard;
    shard.rank = variable_number(rank_name, rank_text, 0);
    shard.size = variable_number(size_name, size_text, 1);
    if (shard.rank >= shard.size)
        throw UsageError(auto_flag, assignment(rank_name, rank_text) + " " + assignment(size_name, size_text),
                         "a rank R and size S with 0 <= R < S");
    shard.source = rank_name + "/" + size_name;
    return shard;
}

// A task of a Slurm job array --array=A-B or A-B:STEP (SLURM_ARRAY_TASK_ID is set).
Shard from_job_array(const Environment& environment)
{
    const std::string id_name = "SLURM_ARRAY_TASK_ID", count_name = "SLURM_ARRAY_TASK_COUNT";
    const std::string min_name = "SLURM_ARRAY_TASK_MIN", step_name = "SLURM_ARRAY_TASK_STEP";
    const std::string id_text = *environment(id_name);
    const std::string count_text = required_variable(environment, count_name, id_name);
    const std::string min_text = environment(min_name).value_or("0");
    const std::string step_text = environment(step_name).value_or("1");
    const std::uint64_t id = variable_number(id_name, id_text, 0), count = variable_number(count_name, count_text, 1);
    const std::uint64_t min = variable_number(min_name, min_text, 0), step = variable_number(step_name, step_text, 1);
    if (id < min || (id - min) % step != 0 || (id - min) / step >= count)
        throw UsageError(auto_flag,
                         assignment(id_name, id_text) + " " + assignment(min_name, min_text) + " " +
                             assignment(step_name, step_text) + " " + assignment(count_name, count_text),
                         "a task of a job array of evenly spaced ids, --array=A-B or --array=A-B:STEP");
    Shard shard;
    shard.rank = (id - min) / step;
    shard.size = count;
    shard.source = id_name + "/" + count_name;
    return shard;
}

// A task of srun (SLURM_PROCID is set).  The batch script of `sbatch -n S`
// has SLURM_PROCID=0 and SLURM_NTASKS=S too, but no SLURM_STEP_ID: there it
// would take shard 0 alone, which is worth a warning.
Shard from_srun(const Environment& environment)
{
    Shard shard = from_rank_and_size(environment, "SLURM_PROCID", "SLURM_NTASKS");
    if (shard.rank == 0 && shard.size > 1 && !environment("SLURM_STEP_ID"))
        shard.warning = "--shard auto: SLURM_PROCID=" + std::to_string(shard.rank) + " of SLURM_NTASKS=" +
                        std::to_string(shard.size) +
                        " outside an srun step (SLURM_STEP_ID is not set): the other shards run only if "
                        "something starts them (`srun ggx sample ...` does)";
    return shard;
}

Shard from_environment(const Environment& environment)
{
    if (environment("OMPI_COMM_WORLD_RANK"))
        return from_rank_and_size(environment, "OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE");
    if (environment("PMI_RANK"))
        return from_rank_and_size(environment, "PMI_RANK", "PMI_SIZE");
    if (environment("SLURM_ARRAY_TASK_ID"))
        return from_job_array(environment);
    if (environment("SLURM_PROCID"))
        return from_srun(environment);
    throw UsageError(auto_flag + ": none of OMPI_COMM_WORLD_RANK, PMI_RANK, SLURM_ARRAY_TASK_ID, SLURM_PROCID is "
                                 "set (run it under mpirun, srun or a Slurm job array, or give --shard R/S)");
}

Shard from_text(const std::string& text)
{
    std::size_t slash = text.find('/');
    if (slash == std::string::npos)
        throw UsageError("--shard", text, explicit_allowed);
    std::optional<std::uint64_t> rank = to_uint64(text.substr(0, slash)), size = to_uint64(text.substr(slash + 1));
    if (!rank || !size || *rank >= *size)
        throw UsageError("--shard", text, explicit_allowed);
    return Shard{*rank, *size, "--shard", ""};
}

// floor(n * r / s) without overflow, for r <= s.
std::uint64_t scaled(std::uint64_t n, std::uint64_t r, std::uint64_t s)
{
    return std::uint64_t((unsigned __int128)n * r / s);
}

} // namespace

std::optional<std::string> process_environment(const std::string& name)
{
    const char* value = std::getenv(name.c_str());
    return value ? std::optional<std::string>(value) : std::nullopt;
}

Shard parse_shard(const std::string& text, const Environment& environment)
{
    return text == "auto" ? from_environment(environment) : from_text(text);
}

ggxcl::SampleRange shard_range(const ggxcl::SampleRange& whole, const Shard& shard)
{
    const std::uint64_t begin = scaled(whole.count, shard.rank, shard.size);
    const std::uint64_t end = scaled(whole.count, shard.rank + 1, shard.size);  // rank + 1 <= size: no overflow
    return {whole.seed, whole.first + begin, end - begin};
}

std::string shard_number(const Shard& shard)
{
    const std::size_t width = std::max<std::size_t>(4, std::to_string(shard.size - 1).size());
    const std::string digits = std::to_string(shard.rank);
    return std::string(width - digits.size(), '0') + digits;
}

std::string shard_out_path(const std::string& out, const Shard& shard)
{
    const std::string placeholder = "{shard}";
    if (out.find(placeholder) == std::string::npos)
        throw UsageError("--out", out,
                         "a path containing {shard} with --shard (replaced by the shard's number, so that the "
                         "shards write separate files), e.g. shards/caps-{shard}.npy");
    std::string path = out;
    const std::string number = shard_number(shard);
    for (std::size_t at = path.find(placeholder); at != std::string::npos; at = path.find(placeholder, at))
        path.replace(at, placeholder.size(), number);
    return path;
}

std::string describe_shard(const Shard& shard, const ggxcl::SampleRange& part, const ggxcl::SampleRange& whole)
{
    return "shard " + std::to_string(shard.rank) + "/" + std::to_string(shard.size) + " (from " + shard.source +
           "): samples [" + std::to_string(part.first) + ", " + std::to_string(part.first + part.count) + ") of [" +
           std::to_string(whole.first) + ", " + std::to_string(whole.first + whole.count) + ")";
}

} // namespace ggxapp
