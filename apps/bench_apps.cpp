// bench_apps.cpp - whole-process timings of `ggx sample` and `ggx histogram`.
#include "bench_apps.hpp"

#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include "child_process.hpp"

namespace ggxapp {

namespace {

namespace fs = std::filesystem;

// Nanoseconds per sample of one run of `ggx ARGUMENTS` (with -n count).
double ns_per_sample(std::vector<std::string> arguments, const std::string& device, std::uint32_t count)
{
    arguments.insert(arguments.end(), {"-n", std::to_string(count)});
    if (!device.empty())
        arguments.insert(arguments.end(), {"--device", device});
    auto start = std::chrono::steady_clock::now();
    ChildOutput child = run_child("/proc/self/exe", arguments);
    std::chrono::duration<double, std::nano> elapsed = std::chrono::steady_clock::now() - start;
    if (!exited_ok(child.status))
        throw std::runtime_error(command_text("ggx", arguments) + " " + describe_exit(child.status) + ": " + child.err);
    return elapsed.count() / count;
}

Timing median_of_runs(const std::vector<std::string>& arguments, const std::string& device, std::uint32_t count)
{
    ns_per_sample(arguments, device, count);  // warms the kernel cache
    std::vector<double> ns;
    for (int run = 0; run < 5; ++run)
        ns.push_back(ns_per_sample(arguments, device, count));
    return summarize(ns);
}

fs::path scratch_folder()
{
    fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    fs::path dir = base / ("ggx-bench-apps-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

} // namespace

AppTimings measure_apps(const std::string& device, std::uint32_t count)
{
    const fs::path dir = scratch_folder();
    AppTimings t;
    t.measured = true;
    t.count = count;
    t.folder = dir.parent_path().string();
    const std::vector<std::string> sample = {"sample", "--method", "caps", "--fields", "m,pdf_m", "--out"};
    auto with_out = [&](std::vector<std::string> words, const std::string& file) {
        words.push_back((dir / file).string());
        return words;
    };
    t.sample_npy = median_of_runs(with_out(sample, "s.npy"), device, count);
    t.histogram = median_of_runs({"histogram", "--method", "caps", "--no-png", "--out", (dir / "h").string()}, device,
                                 count);
    const std::uint32_t text_count = std::min<std::uint32_t>(count, 1u << 20);
    t.text_count = text_count;
    t.sample_csv = ns_per_sample(with_out(sample, "s.csv"), device, text_count);
    t.sample_ply = ns_per_sample(with_out({"sample", "--method", "caps", "--fields", "m", "--out"}, "s.ply"), device,
                                 text_count);
    fs::remove_all(dir);
    return t;
}

} // namespace ggxapp
