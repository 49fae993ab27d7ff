// test_oclgrind.cpp - every kernel of the project run under Oclgrind, a
// simulated OpenCL device that checks every memory access, data race,
// uninitialized value and API call, on small counts; any Oclgrind report
// fails the test.
//
// Each run is `oclgrind --check-api --data-races --uninitialized
// --max-errors N --log LOG PROGRAM ARGS`: Oclgrind becomes the program's
// only OpenCL platform.  Detection (oclgrind_reports): Oclgrind writes its
// kernel reports (invalid reads and writes, data races, uninitialized
// values, "N errors generated") to LOG, but its API errors ("Oclgrind -
// OpenCL runtime error detected") and fatal errors ("OCLGRIND FATAL
// ERROR") to stderr.  The programs run here print nothing on stderr when
// they succeed, so any text in LOG or on stderr counts as a report; the
// report's header lines are what the failure shows.  The negative controls
// (oclgrind_probe: an out-of-bounds write, a copy of never-written memory,
// a write-write race, an API error) show that this detection catches each
// kind, and a correct kernel that it reports nothing.
//
// What runs: `ggx sample` for every method in precise and relaxed mode with
// every field (1000 samples: three whole work-groups of 256 and a partial
// one, so the `_tail` kernels run too; plus a view below the horizon, a
// tilted caps-iso normal, an exact multiple of 256, Sobol points across the
// 2^32 block boundary and the caller's uniforms from a .npy), `ggx histogram
// --no-png` (o and m, 20000 samples: two work-groups of 256 x 64 samples),
// a user sampler (a copy of caps: `ggx sample --sampler`, caps' bits, and
// `ggx histogram --sampler`), `ggx stress` (every method, precise, the
// whole grid), and through
// oclgrind_driver the kernels the command line does not reach: per-sample
// views, alphas and normals, the pdf kernel, the fused furnace (guarded and
// unguarded), world space, a user kernel built with build_user_program, and
// the stress kernel in relaxed mode on a subset of its grid.
// GGXCL_PROGRAM_CACHE and XDG_CACHE_HOME point at a fresh folder per run,
// so no binary cached by another test (or another device) is used.
//
// Oclgrind's default suppression of uniform write-write races (two
// work-items storing the same value to the same address) stays on: the
// `_tail` kernels rely on it by design (work-items past `count` redo the
// last sample and store the same values; ggx_bulk.cl), and
// --uniform-writes reports exactly those stores.
//
// A limit of the method: --uninitialized reports values that come from
// memory never written (a buffer, local memory), but a private variable
// left unset that the compiler folds to `undef` is not seen (a ggx_uniforms that never sets *u2 went
// unreported); building without optimization (--build-options
// -cl-opt-disable) would catch it, but Oclgrind 21.10 then stops with
// "OCLGRIND FATAL ERROR ... Undefined external function:
// llvm.experimental.noalias.scope.decl" on these kernels.
//
// CTest runs the "library" suite as test_oclgrind_library and the rest as
// test_oclgrind, side by side.
//
// Oclgrind's own bug, documented here: clEnqueueFillBuffer does not mark
// the memory it fills as initialized, so atomic_add to a filled buffer is
// reported as "Uninitialized value written to global memory"; the same
// kernel on a buffer written by clEnqueueWriteBuffer is not.  (The library
// therefore zeroes its histogram counts with a write; no suppression.)
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <vector>

#include <nlohmann/json.hpp>

#include "npy_file.hpp"
#include "test_paths.hpp"

namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------
// Detection.

// The header line of every report in Oclgrind's log and in the program's
// stderr: the non-blank lines that do not start with a tab (the details of
// a report are indented).  Both texts are expected to be empty, so any
// other text counts too (its first line stands for it).
std::vector<std::string> oclgrind_reports(const std::string& log, const std::string& err)
{
    std::vector<std::string> reports;
    for (const std::string* text : {&log, &err}) {
        std::istringstream lines(*text);
        std::string line;
        bool any = false, headed = false;
        while (std::getline(lines, line)) {
            if (line.find_first_not_of(" \t\r") == std::string::npos)
                continue;
            any = true;
            if (line[0] != '\t') {
                reports.push_back((text == &log ? "log: " : "stderr: ") + line);
                headed = true;
            }
        }
        if (any && !headed)
            reports.push_back((text == &log ? "log: " : "stderr: ") + text->substr(0, 200));
    }
    return reports;
}

std::string joined(const std::vector<std::string>& lines)
{
    std::string all;
    for (const std::string& line : lines)
        all += line + "\n";
    return all;
}

bool any_contains(const std::vector<std::string>& lines, const std::string& part)
{
    for (const std::string& line : lines)
        if (line.find(part) != std::string::npos)
            return true;
    return false;
}

// ---------------------------------------------------------------------------
// Running a program under Oclgrind.

std::string read_all(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string quoted(const std::string& word)
{
    std::string q = "'";
    for (char c : word)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// oclgrind on PATH, or empty.
std::string find_oclgrind()
{
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        fs::path candidate = fs::path(dir.empty() ? "." : dir) / "oclgrind";
        if (::access(candidate.c_str(), X_OK) == 0)
            return candidate.string();
    }
    return "";
}

const std::string& oclgrind()
{
    static const std::string found = find_oclgrind();
    REQUIRE_MESSAGE(!found.empty(), "oclgrind is not installed (not on PATH): install it with "
                                    "`apt-get install oclgrind` (scripts/install-deps.sh does)");
    return found;
}

// The scratch folder of this process, removed when it exits.
struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("ggx-oclgrind-test-" + std::to_string(::getpid()));
    Scratch() { fs::create_directories(dir); }
    ~Scratch()
    {
        std::error_code ignored;
        fs::remove_all(dir, ignored);
    }
};

const fs::path& scratch()
{
    static Scratch folder;
    return folder.dir;
}

struct Run {
    std::string command;
    int status = -1;  // exit status, -1 when killed by a signal
    std::string out, err, log;
    std::vector<std::string> reports;
};

// PROGRAM ARGS under Oclgrind, with a fresh program cache (and cache home)
// and none of the ggxcl variables that would point elsewhere.
Run run_under_oclgrind(const std::string& program, const std::vector<std::string>& args)
{
    static int runs = 0;
    const fs::path dir = scratch() / ("run-" + std::to_string(++runs));
    fs::create_directories(dir / "cache");
    Run run;
    run.command = "env -u GGXCL_DEVICE -u GGXCL_INJECT_FAULT -u GGXCL_DEVICE_INCLUDE_DIR GGXCL_PROGRAM_CACHE=" +
                  quoted((dir / "cache" / "programs").string()) + " XDG_CACHE_HOME=" + quoted((dir / "cache").string()) +
                  " " + quoted(oclgrind()) + " --check-api --data-races --uninitialized --max-errors 20 --log " +
                  quoted((dir / "oclgrind.log").string()) + " " + quoted(program);
    for (const std::string& arg : args)
        run.command += " " + quoted(arg);
    const std::string shell = run.command + " >" + quoted((dir / "stdout.txt").string()) + " 2>" +
                              quoted((dir / "stderr.txt").string()) + " </dev/null";
    int raw = std::system(shell.c_str());
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    run.out = read_all(dir / "stdout.txt");
    run.err = read_all(dir / "stderr.txt");
    run.log = read_all(dir / "oclgrind.log");  // not created when the program made no OpenCL call
    run.reports = oclgrind_reports(run.log, run.err);
    return run;
}

// The run exited 0 and Oclgrind reported nothing.
void check_clean(const Run& run)
{
    INFO("command: " << run.command);
    INFO("stdout: " << run.out.substr(0, 2000));
    INFO("Oclgrind reports:\n" << joined(run.reports) << "log (start):\n"
                               << run.log.substr(0, 3000) << "\nstderr (start):\n"
                               << run.err.substr(0, 3000));
    CHECK(run.status == 0);
    CHECK(run.reports.empty());
}

// ---------------------------------------------------------------------------
// Reading back what `ggx` wrote.

nlohmann::json read_json(const fs::path& path)
{
    return nlohmann::json::parse(read_all(path), nullptr, false);
}

// The sum of a float64 .npy (version 1.0, as write_npy_f64 writes it).
double sum_f64_npy(const fs::path& path)
{
    const std::string bytes = read_all(path);
    if (bytes.size() < 10 || bytes.compare(0, 6, "\x93NUMPY") != 0)
        return -1.0;
    const std::size_t header = std::size_t((unsigned char)bytes[8]) | std::size_t((unsigned char)bytes[9]) << 8;
    double sum = 0.0;
    for (std::size_t at = 10 + header; at + 8 <= bytes.size(); at += 8) {
        double v;
        std::memcpy(&v, bytes.data() + at, 8);
        sum += v;
    }
    return sum;
}

// A `ggx sample` .npy of all fields: shape (count, 9), finite, unit m and o,
// non-negative pdfs and weight; most pdf_o positive.
void check_sample_file(const fs::path& npy, std::uint64_t count)
{
    ggxapp::NpyArray a = ggxapp::read_npy(npy.string());
    REQUIRE(a.rows == count);
    REQUIRE(a.columns == 9);
    std::uint64_t bad = 0, positive = 0;
    for (std::uint64_t r = 0; r < a.rows; ++r) {
        const float* v = &a.data[r * 9];
        bool ok = true;
        for (int k = 0; k < 9; ++k)
            ok = ok && std::isfinite(v[k]);
        double lm = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
        double lo = std::sqrt(double(v[3]) * v[3] + double(v[4]) * v[4] + double(v[5]) * v[5]);
        ok = ok && std::fabs(lm - 1.0) < 1e-4 && std::fabs(lo - 1.0) < 1e-4 && v[6] >= 0 && v[7] >= 0 && v[8] >= 0;
        bad += !ok;
        positive += v[7] > 0;
    }
    CHECK(bad == 0);
    CHECK(positive > count / 2);
    nlohmann::json side = read_json(fs::path(npy).replace_extension(".json"));
    CHECK(side.value("device", "") == "Oclgrind Simulator");
}

} // namespace

// ---------------------------------------------------------------------------

TEST_SUITE("controls")
{
TEST_CASE("oclgrind is installed and is the only platform of the programs it runs")
{
    Run run = run_under_oclgrind(ggxtest::ggx_binary(), {"devices"});
    check_clean(run);
    CHECK(run.out.find("Oclgrind") != std::string::npos);
    CHECK(run.out.find("1:") == std::string::npos);  // one device only
}

TEST_CASE("the detector reports every deliberately bad kernel, and nothing for a correct one")
{
    struct Control {
        const char* mode;
        const char* header;  // what Oclgrind's report says
    };
    for (const Control& c : {Control{"oob", "Invalid write of size 4 at global memory address"},
                             Control{"uninit", "Uninitialized value written to global memory"},
                             Control{"race", "Write-write data race at global memory address"},
                             Control{"api", "Oclgrind - OpenCL runtime error detected"}}) {
        Run run = run_under_oclgrind(ggxtest::oclgrind_probe(), {c.mode});
        INFO("mode " << c.mode << "\nstdout: " << run.out << "\nreports:\n" << joined(run.reports));
        CHECK(run.status == 0);  // the probe itself succeeded: only the detector sees the fault
        CHECK(run.out.find(std::string("probe ") + c.mode) != std::string::npos);
        CHECK_FALSE(run.reports.empty());
        CHECK(any_contains(run.reports, c.header));
    }
    check_clean(run_under_oclgrind(ggxtest::oclgrind_probe(), {"clean"}));
    // The detector on synthetic text: an indented detail line alone, or any stray text, still counts.
    CHECK(oclgrind_reports("", "").empty());
    CHECK(oclgrind_reports("\n\n", " \n").empty());
    CHECK(oclgrind_reports("\tKernel: k\n", "").size() == 1);
    CHECK(oclgrind_reports("", "OCLGRIND FATAL ERROR (something)\n").size() == 1);
}

TEST_CASE("Oclgrind's bug: atomic_add to a buffer zeroed by clEnqueueFillBuffer is reported, to a written one not")
{
    Run filled = run_under_oclgrind(ggxtest::oclgrind_probe(), {"fill"});
    INFO("fill stdout: " << filled.out << "\nreports:\n" << joined(filled.reports));
    CHECK(filled.status == 0);
    CHECK(filled.out.find("counts 16 16 16 16") != std::string::npos);  // fill did zero the buffer
    CHECK(any_contains(filled.reports, "Uninitialized value written to global memory"));

    Run written = run_under_oclgrind(ggxtest::oclgrind_probe(), {"write"});
    CHECK(written.out.find("counts 16 16 16 16") != std::string::npos);
    check_clean(written);
}
}

TEST_SUITE("cli")
{
TEST_CASE("ggx sample under Oclgrind: every method, precise and relaxed, every field")
{
    const char* methods[] = {"ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded"};
    struct Extra {
        std::vector<std::string> args;
        std::uint64_t count;
    };
    std::vector<Extra> runs;
    for (const char* method : methods)
        for (const char* precision : {"precise", "relaxed"}) {
            // Fast mode anisotropic (caps-iso is isotropic only): the general program; precise the isotropic one.
            std::string alpha = std::string(precision) == "relaxed" && std::string(method) != "caps-iso" ? "0.2,0.4" : "0.3";
            runs.push_back({{"--method", method, "--precision", precision, "--alpha", alpha, "--theta", "60"}, 1000});
        }
    runs.push_back({{"--method", "caps-iso", "--normal", "0,0.6,0.8", "--theta", "30"}, 1000});  // tilted normal
    runs.push_back({{"--method", "caps", "--theta", "120"}, 1000});                            // below the horizon
    runs.push_back({{"--method", "bounded", "--first", "4294967000"}, 512});                     // whole groups only
    runs.push_back({{"--method", "heitz", "--sequence", "sobol", "--first", "4294966900"}, 1000});  // Sobol points
    std::vector<double> uniforms(2 * 1000);
    for (std::size_t j = 0; j < 1000; ++j) {
        uniforms[2 * j] = (double(j) + 0.5) / 1000.0;
        uniforms[2 * j + 1] = std::fmod(double(j) * 0.6180339887498949, 1.0);
    }
    const fs::path uniforms_file = scratch() / "uniforms.npy";
    ggxapp::write_npy_f64(uniforms_file.string(), 1000, 2, uniforms);
    runs.push_back({{"--method", "bounded", "--uniforms", uniforms_file.string()}, 1000});  // the caller's uniforms
    int k = 0;
    for (Extra& r : runs) {
        const fs::path out = scratch() / ("sample-" + std::to_string(++k) + ".npy");
        std::vector<std::string> args = {"sample", "-n", std::to_string(r.count), "--seed", "3",
                                         "--fields", "m,o,pdf_m,pdf_o,weight", "--out", out.string()};
        args.insert(args.end(), r.args.begin(), r.args.end());
        Run run = run_under_oclgrind(ggxtest::ggx_binary(), args);
        check_clean(run);
        if (run.status == 0) {
            INFO(run.command);
            check_sample_file(out, r.count);
        }
    }
}

TEST_CASE("ggx histogram --no-png under Oclgrind: o and m, two work-groups")
{
    for (std::vector<std::string> extra : {std::vector<std::string>{"--method", "caps"},
                                           std::vector<std::string>{"--method", "ndf", "--of", "m", "--precision", "relaxed"},
                                           std::vector<std::string>{"--method", "bounded", "--alpha", "0.2,0.5"}}) {
        const fs::path prefix = scratch() / ("histogram-" + extra[1]);
        std::vector<std::string> args = {"histogram", "-n", "20000", "--bins-z", "16", "--bins-phi", "32",
                                         "--no-png", "--out", prefix.string()};
        args.insert(args.end(), extra.begin(), extra.end());
        Run run = run_under_oclgrind(ggxtest::ggx_binary(), args);
        check_clean(run);
        if (run.status != 0)
            continue;
        INFO(run.command);
        CHECK(sum_f64_npy(prefix.string() + ".observed.npy") == 20000.0);
        nlohmann::json doc = read_json(prefix.string() + ".json");
        CHECK(doc.value("device", "") == "Oclgrind Simulator");
        CHECK(doc.value("count", 0) == 20000);
    }
}
}

TEST_SUITE("user sampler")
{
TEST_CASE("ggx sample and histogram --sampler under Oclgrind: a copy of caps, clean, with caps' bits")
{
    const std::string file = ggxtest::user_samplers_dir() + "/caps_copy.h";
    std::string npy[2];
    int k = 0;
    for (const std::vector<std::string> chosen : {std::vector<std::string>{"--sampler", file},
                                                 std::vector<std::string>{"--method", "caps"}}) {
        const fs::path out = scratch() / ("user-" + std::to_string(k) + ".npy");
        std::vector<std::string> args = {"sample", "-n", "1000", "--seed", "5", "--alpha", "0.2,0.4",
                                         "--fields", "m,o,pdf_m,pdf_o,weight", "--out", out.string()};
        args.insert(args.end(), chosen.begin(), chosen.end());
        Run run = run_under_oclgrind(ggxtest::ggx_binary(), args);
        check_clean(run);
        if (run.status == 0)
            npy[k] = read_all(out);
        ++k;
    }
    CHECK_FALSE(npy[0].empty());
    CHECK(npy[0] == npy[1]);
    const fs::path prefix = scratch() / "user-histogram";
    Run run = run_under_oclgrind(ggxtest::ggx_binary(),
                                 {"histogram", "--sampler", file, "-n", "20000", "--bins-z", "16", "--bins-phi", "32",
                                  "--no-png", "--out", prefix.string()});
    check_clean(run);
    // Every sample binned, or discarded (o below the horizon with weight 0) and counted apart.
    std::ifstream summary(prefix.string() + ".json");
    const double discarded = nlohmann::json::parse(summary)["discarded_samples"].get<double>();
    CHECK(discarded > 0.0);
    CHECK(sum_f64_npy(prefix.string() + ".observed.npy") + discarded == 20000.0);
}
}

TEST_SUITE("stress")
{
TEST_CASE("ggx stress under Oclgrind: every method, precise, the whole grid")
{
    const fs::path prefix = scratch() / "stress";
    Run run = run_under_oclgrind(ggxtest::ggx_binary(),
                                 {"stress", "--methods", "all", "--no-png", "--out", prefix.string()});
    check_clean(run);
    // The totals table: a device and a host row per method, no NaN or Inf on the device.
    int device_rows = 0;
    std::istringstream lines(run.out);
    std::string line;
    while (std::getline(lines, line))
        if (line.find("| device |") != std::string::npos) {
            ++device_rows;
            std::istringstream cells(line);
            std::string cell, values[5];
            for (int c = 0; c < 5 && std::getline(cells, cell, '|'); ++c)
                values[c] = cell;
            INFO(line);
            CHECK(values[4] == " 0 ");  // nan_inf
        }
    CHECK(device_rows == 6);
    CHECK(fs::exists(prefix.string() + ".csv"));
}
}

TEST_SUITE("library")
{
// oclgrind_driver CASE [COUNT]: exit 0, an "ok" line per group, nothing reported.
void check_driver(const std::string& what, const std::string& count, int groups)
{
    Run run = run_under_oclgrind(ggxtest::oclgrind_driver(), {what, count});
    check_clean(run);
    INFO(run.command << "\n" << run.out);
    CHECK(run.out.find("device: Oclgrind Simulator") != std::string::npos);
    int ok = 0;
    for (std::size_t at = run.out.find("\nok "); at != std::string::npos; at = run.out.find("\nok ", at + 1))
        ++ok;
    CHECK(ok == groups);
}

TEST_CASE("per-sample views, alphas and normals, and the pdf kernel on them")
{
    check_driver("per-sample", "1000", 6 * 2);
}

TEST_CASE("the pdf kernel with uniform parameters")
{
    check_driver("pdf", "1000", 6 * 2);
}

TEST_CASE("the fused furnace, unguarded and guarded, uniform and per-sample (two work-groups of 64)")
{
    check_driver("furnace", "1001", 6 * 3);
}

TEST_CASE("world space: a tilted normal, and per-sample normals and views")
{
    check_driver("world", "1000", 6 * 2);
}

TEST_CASE("a user kernel including ggx_samplers.h gives Sampler::enqueue's bits")
{
    check_driver("user", "1000", 6);
}

TEST_CASE("the stress kernel in relaxed mode on every 16th case of the grid")
{
    check_driver("stress", "16", 6);
}
}
