// bench_native.cpp - timings and error of the native C++ baseline, run as
// the child process ggx-native (bench/native/ggx_native_main.cpp has the
// protocol): timings come back as one line of ns per sample per repeat,
// samples as raw float32 m and pdf_m, compared here with the reference.
#include "bench_native.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "child_process.hpp"
#include "reference_bridge.hpp"

namespace ggxapp {

namespace {

namespace fs = std::filesystem;

const char* native_job_name(BenchJob job)
{
    switch (job) {
    case BenchJob::write: return "write_m_pdf_m";
    case BenchJob::furnace: return "furnace_sum";
    case BenchJob::world: return "world_space_o";
    case BenchJob::write_o:
    case BenchJob::per_sample:
    case BenchJob::store: break;  // device-only jobs
    }
    return "write_m_pdf_m";
}

bool is_executable(const fs::path& path)
{
    std::error_code ignored;
    return fs::is_regular_file(path, ignored) && ::access(path.c_str(), X_OK) == 0;
}

// $GGX_NATIVE, else ggx-native next to this program, else ../libexec/ggxcl/ggx-native from it.
std::string native_program()
{
    const char* chosen = std::getenv("GGX_NATIVE");
    if (chosen && *chosen) {
        if (!is_executable(chosen))
            throw NativeBaselineError(std::string("ggx-native not found: GGX_NATIVE=") + chosen +
                                      " is not an executable file");
        return chosen;
    }
    std::error_code error;
    fs::path self = fs::read_symlink("/proc/self/exe", error);
    if (error)
        throw NativeBaselineError("ggx-native not found: set GGX_NATIVE (/proc/self/exe: " + error.message() + ")");
    const fs::path folder = self.parent_path();
    const fs::path places[] = {folder / "ggx-native", (folder / ".." / "libexec" / "ggxcl" / "ggx-native").lexically_normal()};
    for (const fs::path& place : places)
        if (is_executable(place))
            return place.string();
    throw NativeBaselineError("ggx-native not found: set GGX_NATIVE (looked for " + places[0].string() + " and " +
                              places[1].string() + ")");
}

// Enough digits that ggx-native reads back the same float.
std::string text_of(float value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

std::string text_of(std::uint64_t value)
{
    return std::to_string(value);
}

struct NativeRun {
    std::string command;
    std::string out;
};

// Runs ggx-native with `arguments`; throws NativeBaselineError naming the command unless it succeeds.
NativeRun run_native(const std::vector<std::string>& arguments)
{
    const std::string program = native_program();
    NativeRun run{command_text(program, arguments), {}};
    ChildOutput child;
    try {
        child = run_child(program, arguments);
    } catch (const std::exception& e) {
        throw NativeBaselineError(e.what());
    }
    if (!exited_ok(child.status)) {
        std::string said = child.err.substr(0, child.err.find('\n'));
        throw NativeBaselineError("`" + run.command + "` " + describe_exit(child.status) +
                                  (said.empty() ? "" : ": " + said));
    }
    run.out = std::move(child.out);
    return run;
}

// `repeats` lines of positive, finite ns per sample.
Timing timing_of(const NativeRun& run, int repeats)
{
    std::istringstream lines(run.out);
    std::vector<double> ns;
    std::string line;
    while (std::getline(lines, line)) {
        char* end = nullptr;
        double value = std::strtod(line.c_str(), &end);
        if (line.empty() || end != line.c_str() + line.size() || !std::isfinite(value) || !(value > 0))
            throw NativeBaselineError("`" + run.command + "` printed '" + line.substr(0, 80) +
                                      "' where a time in ns per sample belongs");
        ns.push_back(value);
    }
    if (ns.size() != std::size_t(repeats))
        throw NativeBaselineError("`" + run.command + "` printed " + std::to_string(ns.size()) + " timings, not " +
                                  std::to_string(repeats));
    return summarize(ns);
}

std::vector<std::string> timed_arguments(const NativeSetup& setup)
{
    return {text_of(std::uint64_t(setup.count)), std::to_string(setup.threads), std::to_string(setup.repeats),
            text_of(setup.alpha), text_of(setup.view.x), text_of(setup.view.y), text_of(setup.view.z)};
}

} // namespace

Timing native_timing(ggxcl::Method method, BenchJob job, const NativeSetup& setup)
{
    std::vector<std::string> arguments = {"time", std::string(ggxcl::method_name(method)), native_job_name(job)};
    for (std::string& a : timed_arguments(setup))
        arguments.push_back(std::move(a));
    return timing_of(run_native(arguments), setup.repeats);
}

Timing native_vectorized_timing(ggxcl::Method method, const NativeSetup& setup)
{
    std::vector<std::string> arguments = {"vectorized", std::string(ggxcl::method_name(method))};
    for (std::string& a : timed_arguments(setup))
        arguments.push_back(std::move(a));
    return timing_of(run_native(arguments), setup.repeats);
}

NumericalError native_numerical_error(ggxcl::Method method)
{
    const std::uint64_t count = accuracy_samples;
    std::vector<double> angles, pdfs;
    NumericalError error;
    for (const ggxcl::SampleParams& p : accuracy_configs(method, ggxcl::Precision::precise)) {
        NativeRun run = run_native({"write", std::string(ggxcl::method_name(method)), text_of(p.alpha_x),
                                    text_of(p.alpha_y), text_of(p.view.x), text_of(p.view.y), text_of(p.view.z),
                                    text_of(accuracy_seed), text_of(count)});
        if (run.out.size() != 4 * count * sizeof(float))
            throw NativeBaselineError("`" + run.command + "` wrote " + std::to_string(run.out.size()) +
                                      " bytes, not " + std::to_string(4 * count * sizeof(float)) +
                                      " (m and pdf_m as float32)");
        std::vector<float> m(3 * count), pdf_m(count);
        std::memcpy(m.data(), run.out.data(), m.size() * sizeof(float));
        std::memcpy(pdf_m.data(), run.out.data() + m.size() * sizeof(float), pdf_m.size() * sizeof(float));
        ggxref::Params ref = ggxbridge::reference_params(p);
        for (std::uint64_t j = 0; j < count; ++j) {
            std::array<double, 2> u = ggxref::uniforms(accuracy_seed, j);
            ggxref::Sample r = ggxref::sample(ggxbridge::reference_method(method), ref, u[0], u[1]);
            double angle = angle_between({m[j], m[count + j], m[2 * count + j]}, r.m);
            if (!std::isfinite(angle) || !std::isfinite(pdf_m[j])) {
                ++error.non_finite;
                continue;
            }
            angles.push_back(angle);
            pdfs.push_back(relative_error(pdf_m[j], r.pdf_m));
        }
    }
    percentiles(angles, error.angle_p99, error.angle_max);
    percentiles(pdfs, error.pdf_p99, error.pdf_max);
    return error;
}

} // namespace ggxapp
