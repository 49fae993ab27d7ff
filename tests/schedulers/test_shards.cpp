// test_shards.cpp - `ggx sample --shard R/S | auto` without a launcher: the
// ranges (exact for 64-bit counts), the shard numbers in file names, shards
// that merge to exactly one run's file (also empty shards and shards of
// --uniforms rows), `auto` from each launcher's variables and their order
// of precedence, and every usage error (exit 2, a message naming the value
// and what is allowed, no file written).  The tool runs with every
// launcher variable unset but those a case sets, whatever surrounds the test.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <sys/wait.h>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "cli_values.hpp"
#include "npy_file.hpp"
#include "shard_option.hpp"

namespace fs = std::filesystem;

namespace {

using ggxtest::read_all;
using Variables = std::map<std::string, std::string>;

const std::vector<std::string> launcher_variables = {
    "OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE", "PMI_RANK",     "PMI_SIZE",
    "SLURM_ARRAY_TASK_ID",  "SLURM_ARRAY_TASK_COUNT", "SLURM_ARRAY_TASK_MIN", "SLURM_ARRAY_TASK_STEP",
    "SLURM_PROCID",         "SLURM_NTASKS",         "SLURM_STEP_ID"};

const std::string caps = "sample --method caps --alpha 0.2 --theta 70 --seed 7 --fields o,pdf_o,weight ";

fs::path scratch()
{
    static fs::path dir = ggxtest::scratch_dir("shards");
    return dir;
}

// A fresh, empty folder in the scratch folder.
fs::path folder(const std::string& name)
{
    fs::path dir = scratch() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

struct Result {
    int status;
    std::string out, err;
};

// `ggx ARGS` with only `variables` of the launchers' set.
Result ggx(const std::string& args, const Variables& variables = {})
{
    std::string command = "env";
    for (const std::string& name : launcher_variables)
        command += " -u " + name;
    for (const auto& [name, value] : variables)
        command += " '" + name + "=" + value + "'";
    const fs::path out = scratch() / "stdout.txt", err = scratch() / "stderr.txt";
    command += " " + ggxtest::ggx_binary() + " " + args + " >" + out.string() + " 2>" + err.string();
    int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_all(out), read_all(err)};
}

nlohmann::json sidecar(const fs::path& path) { return nlohmann::json::parse(std::ifstream(path)); }

std::size_t files_in(const fs::path& dir)
{
    std::size_t n = 0;
    for (const auto& entry : fs::directory_iterator(dir))
        n += entry.is_regular_file();
    return n;
}

// A lookup in `variables`, as parse_shard reads the environment.
ggxapp::Environment environment(const Variables& variables)
{
    return [variables](const std::string& name) -> std::optional<std::string> {
        auto found = variables.find(name);
        return found == variables.end() ? std::nullopt : std::optional<std::string>(found->second);
    };
}

ggxapp::Shard shard_of(std::uint64_t rank, std::uint64_t size) { return {rank, size, "--shard", ""}; }

} // namespace

TEST_CASE("shard ranges are floor(N*R/S) .. floor(N*(R+1)/S) from --first, exact for 64-bit counts")
{
    const std::uint64_t max = ~std::uint64_t(0);
    const ggxcl::SampleRange ten{7, 5, 10};
    CHECK(ggxapp::shard_range(ten, shard_of(0, 3)).first == 5);
    CHECK(ggxapp::shard_range(ten, shard_of(0, 3)).count == 3);
    CHECK(ggxapp::shard_range(ten, shard_of(1, 3)).first == 8);
    CHECK(ggxapp::shard_range(ten, shard_of(1, 3)).count == 3);
    CHECK(ggxapp::shard_range(ten, shard_of(2, 3)).first == 11);
    CHECK(ggxapp::shard_range(ten, shard_of(2, 3)).count == 4);
    CHECK(ggxapp::shard_range(ten, shard_of(2, 3)).seed == 7);

    // N * R overflows 64 bits here: 2^64-1 samples over 3 and over 2^64-1 shards.
    const ggxcl::SampleRange all{0, 0, max};
    CHECK(ggxapp::shard_range(all, shard_of(1, 3)).first == 6148914691236517205ull);
    CHECK(ggxapp::shard_range(all, shard_of(2, 3)).first == 12297829382473034410ull);
    CHECK(ggxapp::shard_range(all, shard_of(2, 3)).count == 6148914691236517205ull);
    CHECK(ggxapp::shard_range(all, shard_of(max - 1, max)).first == max - 1);
    CHECK(ggxapp::shard_range(all, shard_of(max - 1, max)).count == 1);
    // Beyond 2^63 samples: the first shard starts at --first, the last ends
    // with the job, and every shard holds floor(N/S) or ceil(N/S) samples.
    const ggxcl::SampleRange big{0, 1, (std::uint64_t(1) << 63) + 12345};
    for (std::uint64_t size : std::vector<std::uint64_t>{2, 3, 7, 1000003, max - 1}) {
        CAPTURE(size);
        CHECK(ggxapp::shard_range(big, shard_of(0, size)).first == big.first);
        ggxcl::SampleRange last = ggxapp::shard_range(big, shard_of(size - 1, size));
        CHECK(last.first + last.count == big.first + big.count);
        for (std::uint64_t rank : std::vector<std::uint64_t>{0, 1, size / 2, size - 1}) {
            std::uint64_t count = ggxapp::shard_range(big, shard_of(rank, size)).count;
            CHECK((count == big.count / size || count == big.count / size + 1));
        }
    }
    // Consecutive and complete: every shard of a small S.
    for (std::uint64_t size = 1; size <= 40; ++size) {
        std::uint64_t next = big.first;
        for (std::uint64_t rank = 0; rank < size; ++rank) {
            ggxcl::SampleRange part = ggxapp::shard_range(big, shard_of(rank, size));
            CHECK(part.first == next);
            next = part.first + part.count;
        }
        CHECK(next == big.first + big.count);
    }
    // S > N: shards of no sample, the others of one.
    const ggxcl::SampleRange two{0, 0, 2};
    CHECK(ggxapp::shard_range(two, shard_of(0, 5)).count == 0);
    CHECK(ggxapp::shard_range(two, shard_of(4, 5)).count == 1);
}

TEST_CASE("shard numbers have 4 digits, or as many as S - 1 has, so that globs list them in order")
{
    CHECK(ggxapp::shard_number(shard_of(7, 16)) == "0007");
    CHECK(ggxapp::shard_number(shard_of(9999, 10000)) == "9999");
    CHECK(ggxapp::shard_number(shard_of(7, 10001)) == "00007");
    CHECK(ggxapp::shard_number(shard_of(12, ~std::uint64_t(0))) == "00000000000000000012");
    CHECK(ggxapp::shard_out_path("a/{shard}/caps-{shard}.npy", shard_of(3, 4)) == "a/0003/caps-0003.npy");
    CHECK_THROWS_AS(ggxapp::shard_out_path("caps.npy", shard_of(3, 4)), ggxapp::UsageError);
}

TEST_CASE("parse_shard: R/S, and auto from each launcher in order of precedence")
{
    using ggxapp::parse_shard;
    ggxapp::Shard s = parse_shard("2/5", environment({}));
    CHECK((s.rank == 2 && s.size == 5 && s.source == "--shard"));
    s = parse_shard("18446744073709551614/18446744073709551615", environment({}));
    CHECK(s.rank == 18446744073709551614ull);

    const Variables everything = {{"OMPI_COMM_WORLD_RANK", "1"}, {"OMPI_COMM_WORLD_SIZE", "4"},
                                  {"PMI_RANK", "2"},             {"PMI_SIZE", "5"},
                                  {"SLURM_ARRAY_TASK_ID", "13"}, {"SLURM_ARRAY_TASK_MIN", "10"},
                                  {"SLURM_ARRAY_TASK_COUNT", "6"}, {"SLURM_PROCID", "0"},
                                  {"SLURM_NTASKS", "1"}};
    Variables v = everything;
    s = parse_shard("auto", environment(v));
    CHECK((s.rank == 1 && s.size == 4 && s.source == "OMPI_COMM_WORLD_RANK/OMPI_COMM_WORLD_SIZE"));
    v.erase("OMPI_COMM_WORLD_RANK");  // (its size alone is no rank)
    s = parse_shard("auto", environment(v));
    CHECK((s.rank == 2 && s.size == 5 && s.source == "PMI_RANK/PMI_SIZE"));
    v.erase("PMI_RANK");
    s = parse_shard("auto", environment(v));
    CHECK((s.rank == 3 && s.size == 6 && s.source == "SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT"));
    v.erase("SLURM_ARRAY_TASK_ID");
    s = parse_shard("auto", environment(v));
    CHECK((s.rank == 0 && s.size == 1 && s.source == "SLURM_PROCID/SLURM_NTASKS"));

    // Arrays: SLURM_ARRAY_TASK_MIN defaults to 0; --array=A-B:STEP counts in steps.
    s = parse_shard("auto", environment({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "3"}}));
    CHECK((s.rank == 2 && s.size == 3));
    s = parse_shard("auto", environment({{"SLURM_ARRAY_TASK_ID", "25"}, {"SLURM_ARRAY_TASK_MIN", "5"},
                                         {"SLURM_ARRAY_TASK_STEP", "10"}, {"SLURM_ARRAY_TASK_COUNT", "3"}}));
    CHECK((s.rank == 2 && s.size == 3));

    // srun: a warning only for the batch script of `sbatch -n S` (rank 0, no step).
    s = parse_shard("auto", environment({{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "4"}}));
    CHECK(s.warning.find("SLURM_STEP_ID") != std::string::npos);
    s = parse_shard("auto", environment({{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "4"}, {"SLURM_STEP_ID", "0"}}));
    CHECK(s.warning.empty());
}

TEST_CASE("shards of N=10 over S=3 hold 3, 3 and 4 samples and merge to exactly one run, .npy and .csv")
{
    for (const std::string ext : {".npy", ".csv"}) {
        CAPTURE(ext);
        fs::path dir = folder("ten" + ext.substr(1));
        for (int rank = 0; rank < 3; ++rank) {
            Result r = ggx(caps + "-n 10 --first 5 --shard " + std::to_string(rank) + "/3 --out " +
                           (dir / ("s-{shard}" + ext)).string());
            REQUIRE(r.status == 0);
            CHECK(r.out.find("shard " + std::to_string(rank) + "/3 (from --shard)") != std::string::npos);
        }
        CHECK(ggx(caps + "-n 10 --first 5 --out " + (dir / ("one" + ext)).string()).status == 0);
        const int counts[3] = {3, 3, 4}, firsts[3] = {5, 8, 11};
        for (int rank = 0; rank < 3; ++rank) {
            nlohmann::json doc = sidecar(dir / ("s-000" + std::to_string(rank) + ".json"));
            CHECK(doc["count"] == counts[rank]);
            CHECK(doc["first"] == firsts[rank]);
        }
        if (ext == ".npy")
            CHECK(ggxapp::read_npy((dir / "s-0002.npy").string()).rows == 4);
        std::string shards = (dir / ("s-0000" + ext)).string() + " " + (dir / ("s-0001" + ext)).string() + " " +
                             (dir / ("s-0002" + ext)).string();
        REQUIRE(ggx("merge --out " + (dir / ("m" + ext)).string() + " " + shards).status == 0);
        CHECK(read_all(dir / ("m" + ext)) == read_all(dir / ("one" + ext)));
        CHECK(read_all(dir / "m.json") == read_all(dir / "one.json"));
    }
}

TEST_CASE("shards of no sample (S > N) are valid empty files that ggx merge takes")
{
    fs::path dir = folder("empty");
    std::string shards;
    for (int rank = 0; rank < 5; ++rank) {
        Result r = ggx(caps + "-n 2 --shard " + std::to_string(rank) + "/5 --out " + (dir / "e-{shard}.npy").string());
        REQUIRE(r.status == 0);
        shards += " " + (dir / ("e-000" + std::to_string(rank) + ".npy")).string();
    }
    ggxapp::NpyArray empty = ggxapp::read_npy((dir / "e-0000.npy").string());
    CHECK(empty.rows == 0);
    CHECK(empty.columns == 5);
    nlohmann::json doc = sidecar(dir / "e-0000.json");
    CHECK(doc["count"] == 0);
    CHECK(doc["shape"][0] == 0);
    REQUIRE(ggx("merge --out " + (dir / "m.npy").string() + shards).status == 0);
    REQUIRE(ggx(caps + "-n 2 --out " + (dir / "one.npy").string()).status == 0);
    CHECK(read_all(dir / "m.npy") == read_all(dir / "one.npy"));
    CHECK(read_all(dir / "m.json") == read_all(dir / "one.json"));
}

TEST_CASE("--shard with --uniforms takes the shard's rows of the file")
{
    fs::path dir = folder("uniforms");
    std::vector<double> u(2 * 11);
    for (std::size_t k = 0; k < u.size(); ++k)
        u[k] = double((k * 37) % 101) / 101.0;
    const std::string uniforms = (dir / "u.npy").string();
    ggxapp::write_npy_f64(uniforms, 11, 2, u);
    const std::string heitz = "sample --method heitz --alpha 0.3 --uniforms " + uniforms + " --fields m,u ";
    std::string shards;
    for (int rank = 0; rank < 4; ++rank) {
        REQUIRE(ggx(heitz + "--shard " + std::to_string(rank) + "/4 --out " + (dir / "s-{shard}.npy").string()).status ==
                0);
        shards += " " + (dir / ("s-000" + std::to_string(rank) + ".npy")).string();
    }
    CHECK(sidecar(dir / "s-0001.json")["count"] == 3);  // rows 2, 3, 4
    CHECK(sidecar(dir / "s-0001.json")["first"] == 2);
    REQUIRE(ggx("merge --out " + (dir / "m.npy").string() + shards).status == 0);
    REQUIRE(ggx(heitz + "--out " + (dir / "one.npy").string()).status == 0);
    CHECK(read_all(dir / "m.npy") == read_all(dir / "one.npy"));
    CHECK(read_all(dir / "m.json") == read_all(dir / "one.json"));
    // -n still counts the whole file's rows.
    Result r = ggx(heitz + "-n 3 --shard 0/4 --out " + (dir / "x-{shard}.npy").string());
    CHECK(r.status == 2);
    CHECK(r.err.find("-n: invalid value '3'") != std::string::npos);
}

TEST_CASE("--shard auto takes each launcher's rank and size, in order of precedence")
{
    struct Case {
        Variables variables;
        std::string shard;   // "R/S" expected
        std::string source;  // variables named in the summary
    };
    const std::vector<Case> cases = {
        {{{"OMPI_COMM_WORLD_RANK", "1"}, {"OMPI_COMM_WORLD_SIZE", "3"}}, "1/3", "OMPI_COMM_WORLD_RANK/OMPI_COMM_WORLD_SIZE"},
        {{{"PMI_RANK", "2"}, {"PMI_SIZE", "3"}}, "2/3", "PMI_RANK/PMI_SIZE"},
        {{{"SLURM_ARRAY_TASK_ID", "11"}, {"SLURM_ARRAY_TASK_MIN", "10"}, {"SLURM_ARRAY_TASK_COUNT", "3"}, {"SLURM_PROCID", "0"}},
         "1/3", "SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT"},
        {{{"SLURM_PROCID", "2"}, {"SLURM_NTASKS", "3"}, {"SLURM_STEP_ID", "0"}}, "2/3", "SLURM_PROCID/SLURM_NTASKS"},
        // Precedence: Open MPI, then PMI, then the job array, then srun.
        {{{"OMPI_COMM_WORLD_RANK", "0"}, {"OMPI_COMM_WORLD_SIZE", "3"}, {"PMI_RANK", "1"}, {"PMI_SIZE", "3"},
          {"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "3"}, {"SLURM_PROCID", "1"}, {"SLURM_NTASKS", "3"}},
         "0/3", "OMPI_COMM_WORLD_RANK/OMPI_COMM_WORLD_SIZE"},
        {{{"PMI_RANK", "1"}, {"PMI_SIZE", "3"}, {"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "3"},
          {"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "3"}},
         "1/3", "PMI_RANK/PMI_SIZE"},
        {{{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "3"}, {"SLURM_PROCID", "1"}, {"SLURM_NTASKS", "3"}},
         "2/3", "SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT"},
    };
    const int firsts[3] = {0, 3, 6}, counts[3] = {3, 3, 4};
    for (const Case& c : cases) {
        CAPTURE(c.source);
        fs::path dir = folder("auto");
        Result r = ggx(caps + "-n 10 --shard auto --out " + (dir / "a-{shard}.npy").string(), c.variables);
        REQUIRE(r.status == 0);
        CHECK(r.err.empty());
        CHECK(r.out.find("shard " + c.shard + " (from " + c.source + ")") != std::string::npos);
        const int rank = c.shard[0] - '0';
        nlohmann::json doc = sidecar(dir / ("a-000" + std::to_string(rank) + ".json"));
        CHECK(doc["first"] == firsts[rank]);
        CHECK(doc["count"] == counts[rank]);
        CHECK(files_in(dir) == 2);
    }
}

TEST_CASE("the batch script of `sbatch -n S` (SLURM_PROCID=0 outside a step) samples shard 0 with a warning")
{
    fs::path dir = folder("batch");
    Result r = ggx(caps + "-n 10 --shard auto --out " + (dir / "b-{shard}.npy").string(),
                   {{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "2"}});
    CHECK(r.status == 0);
    CHECK(r.err.find("ggx: warning: --shard auto: SLURM_PROCID=0 of SLURM_NTASKS=2 outside an srun step") !=
          std::string::npos);
    CHECK(fs::exists(dir / "b-0000.npy"));
}

TEST_CASE("bad --shard, --out or launcher variables: exit 2, one line naming the value and what is allowed, no file")
{
    struct Case {
        std::string shard, out;
        Variables variables;
        std::string message;  // what stderr must contain
    };
    const std::string range_form = "allowed is a shard R/S with whole numbers 0 <= R < S, or auto";
    const std::string none_set =
        "--shard auto: none of OMPI_COMM_WORLD_RANK, PMI_RANK, SLURM_ARRAY_TASK_ID, SLURM_PROCID is set";
    const std::vector<Case> cases = {
        {"3/3", "s-{shard}.npy", {}, "--shard: invalid value '3/3': " + range_form},
        {"0/0", "s-{shard}.npy", {}, "--shard: invalid value '0/0': " + range_form},
        {"1", "s-{shard}.npy", {}, "--shard: invalid value '1': " + range_form},
        {"-1/3", "s-{shard}.npy", {}, "--shard: invalid value '-1/3': " + range_form},
        {"1/3/4", "s-{shard}.npy", {}, "--shard: invalid value '1/3/4': " + range_form},
        {"a/b", "s-{shard}.npy", {}, "--shard: invalid value 'a/b': " + range_form},
        {"''", "s-{shard}.npy", {}, "--shard: invalid value '': " + range_form},
        {" 1/3", "s-{shard}.npy", {}, "--shard: invalid value ' 1/3': " + range_form},
        {"1/18446744073709551616", "s-{shard}.npy", {}, "--shard: invalid value '1/18446744073709551616'"},
        {"1/3", "s.npy", {}, "--out: invalid value '%/s.npy': allowed is a path containing {shard} with --shard"},
        {"", "s-{shard}.npy", {}, "--out: invalid value '%/s-{shard}.npy': allowed is a path without {shard}"},
        {"auto", "s-{shard}.npy", {}, none_set},
        {"auto", "s-{shard}.npy", {{"OMPI_COMM_WORLD_SIZE", "3"}, {"PMI_SIZE", "3"}, {"SLURM_NTASKS", "3"}}, none_set},
        {"auto", "s-{shard}.npy", {{"OMPI_COMM_WORLD_RANK", "1"}},
         "--shard auto: OMPI_COMM_WORLD_RANK is set but OMPI_COMM_WORLD_SIZE is not"},
        {"auto", "s-{shard}.npy", {{"OMPI_COMM_WORLD_RANK", "one"}, {"OMPI_COMM_WORLD_SIZE", "3"}},
         "--shard auto: invalid value 'OMPI_COMM_WORLD_RANK=one': allowed is a whole number from 0 to 2^64-1"},
        {"auto", "s-{shard}.npy", {{"OMPI_COMM_WORLD_RANK", ""}, {"OMPI_COMM_WORLD_SIZE", "3"}},
         "--shard auto: invalid value 'OMPI_COMM_WORLD_RANK=': allowed is a whole number from 0 to 2^64-1"},
        {"auto", "s-{shard}.npy", {{"OMPI_COMM_WORLD_RANK", "1"}, {"OMPI_COMM_WORLD_SIZE", "0"}},
         "--shard auto: invalid value 'OMPI_COMM_WORLD_SIZE=0': allowed is a whole number from 1 to 2^64-1"},
        {"auto", "s-{shard}.npy", {{"OMPI_COMM_WORLD_RANK", "3"}, {"OMPI_COMM_WORLD_SIZE", "3"}},
         "--shard auto: invalid value 'OMPI_COMM_WORLD_RANK=3 OMPI_COMM_WORLD_SIZE=3': allowed is a rank R and size S "
         "with 0 <= R < S"},
        {"auto", "s-{shard}.npy", {{"PMI_RANK", "0"}, {"PMI_SIZE", "18446744073709551616"}},
         "--shard auto: invalid value 'PMI_SIZE=18446744073709551616': allowed is a whole number from 1 to 2^64-1"},
        {"auto", "s-{shard}.npy", {{"PMI_RANK", "+1"}, {"PMI_SIZE", "3"}}, "invalid value 'PMI_RANK=+1'"},
        {"auto", "s-{shard}.npy", {{"SLURM_ARRAY_TASK_ID", "1"}},
         "--shard auto: SLURM_ARRAY_TASK_ID is set but SLURM_ARRAY_TASK_COUNT is not"},
        {"auto", "s-{shard}.npy", {{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_COUNT", "3"}},
         "--shard auto: invalid value 'SLURM_ARRAY_TASK_ID=x'"},
        {"auto", "s-{shard}.npy", {{"SLURM_ARRAY_TASK_ID", "5"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_COUNT", "3"}},
         "--shard auto: invalid value 'SLURM_ARRAY_TASK_ID=5 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_STEP=1 "
         "SLURM_ARRAY_TASK_COUNT=3': allowed is a task of a job array of evenly spaced ids"},
        {"auto", "s-{shard}.npy",
         {{"SLURM_ARRAY_TASK_ID", "6"}, {"SLURM_ARRAY_TASK_STEP", "4"}, {"SLURM_ARRAY_TASK_COUNT", "3"}},
         "allowed is a task of a job array of evenly spaced ids"},
        {"auto", "s-{shard}.npy", {{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "3"}, {"SLURM_ARRAY_TASK_MIN", "a"}},
         "invalid value 'SLURM_ARRAY_TASK_MIN=a'"},
        {"auto", "s-{shard}.npy", {{"SLURM_PROCID", "1"}}, "--shard auto: SLURM_PROCID is set but SLURM_NTASKS is not"},
        {"auto", "s-{shard}.npy", {{"SLURM_PROCID", "1"}, {"SLURM_NTASKS", "2x"}},
         "--shard auto: invalid value 'SLURM_NTASKS=2x': allowed is a whole number from 1 to 2^64-1"},
        // An earlier launcher's bad variable is reported, not skipped for a later one's good ones.
        {"auto", "s-{shard}.npy", {{"PMI_RANK", "x"}, {"PMI_SIZE", "3"}, {"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "1"}},
         "invalid value 'PMI_RANK=x'"},
    };
    for (const Case& c : cases) {
        fs::path dir = folder("bad");
        std::string message = c.message;
        if (message.find('%') != std::string::npos)
            message.replace(message.find('%'), 1, dir.string());
        CAPTURE(c.shard);
        CAPTURE(message);
        const std::string shard = c.shard.empty() ? "" : c.shard == "''" ? "--shard '' " : "--shard '" + c.shard + "' ";
        Result r = ggx(caps + "-n 10 " + shard + "--out " + (dir / c.out).string(), c.variables);
        CHECK(r.status == 2);
        CHECK(r.err.find(message) != std::string::npos);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(files_in(dir) == 0);
    }
}
