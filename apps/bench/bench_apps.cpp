// bench_apps.cpp - whole-process timings of `ggx`: its start-up, `ggx sample` and `ggx histogram`.
#include "bench_apps.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "atomic_file.hpp"
#include "child_process.hpp"

namespace ggxapp {

namespace {

namespace fs = std::filesystem;

// Wall-clock seconds of one run of `ggx ARGUMENTS` on `device`, its environment changed by `settings`.
double timed_ggx(std::vector<std::string> arguments, const DeviceArguments& device,
                 const std::vector<std::string>& settings = {})
{
    arguments.insert(arguments.end(), device.begin(), device.end());
    const auto start = std::chrono::steady_clock::now();
    const ChildOutput child = run_child("/proc/self/exe", arguments, 0, settings);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (!exited_ok(child.status))
        throw std::runtime_error(command_text("ggx", arguments) + " " + describe_exit(child.status) + ": " + child.err);
    return elapsed.count();
}

// Nanoseconds per sample of one run of `ggx ARGUMENTS` (with -n count).
double ns_per_sample(std::vector<std::string> arguments, const DeviceArguments& device, std::uint32_t count)
{
    arguments.insert(arguments.end(), {"-n", std::to_string(count)});
    return timed_ggx(arguments, device) * 1e9 / count;
}

// Every run writes new files: those of the run before are removed first (a
// replaced file's pages would be freed inside the timed run).
Timing median_of_runs(const std::vector<std::string>& arguments, const DeviceArguments& device, std::uint32_t count,
                      const fs::path& dir)
{
    auto clear = [&] {
        for (const fs::directory_entry& entry : fs::directory_iterator(dir))
            fs::remove(entry.path());
    };
    clear();
    ns_per_sample(arguments, device, count);  // warms the kernel cache
    std::vector<double> ns;
    for (int run = 0; run < 5; ++run) {
        clear();
        ns.push_back(ns_per_sample(arguments, device, count));
    }
    return summarize(ns);
}

// Nanoseconds per sample of writing `bytes_per_sample` bytes per sample from
// memory into a new file in `dir`, 1 MiB per write: what the file alone
// costs there, whatever computed the bytes.  Median of 5.
Timing file_write_floor(const fs::path& dir, std::uint32_t count, std::size_t bytes_per_sample)
{
    const std::vector<char> block(1u << 20, 1);
    std::vector<double> ns;
    for (int run = 0; run < 5; ++run) {
        const fs::path path = dir / "floor.bin";
        fs::remove(path);
        auto start = std::chrono::steady_clock::now();
        {
            AtomicFile file(path.string());
            for (std::uint64_t left = std::uint64_t(count) * bytes_per_sample; left > 0;) {
                const std::size_t n = std::size_t(std::min<std::uint64_t>(left, block.size()));
                file.write(block.data(), n);
                left -= n;
            }
            file.commit();
        }
        std::chrono::duration<double, std::nano> elapsed = std::chrono::steady_clock::now() - start;
        ns.push_back(elapsed.count() / count);
    }
    fs::remove(dir / "floor.bin");
    return summarize(ns);
}

// The device seconds per sample that `ggx histogram` recorded in its sidecar.
double recorded_device_ns(const fs::path& sidecar, std::uint32_t count)
{
    std::ifstream in(sidecar);
    return nlohmann::json::parse(in).at("device_seconds").get<double>() * 1e9 / count;
}

fs::path scratch_folder()
{
    fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    fs::path dir = base / ("ggx-bench-apps-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

} // namespace

StartupTiming measure_startup(const DeviceArguments& device, int warm_runs)
{
    const fs::path dir = fs::temp_directory_path() / ("ggx-startup-" + std::to_string(::getpid()));
    fs::create_directories(dir / "cache");
    const std::vector<std::string> one_sample = {"sample", "--method", "caps", "-n", "1", "--out",
                                                 (dir / "one.npy").string()};
    const std::vector<std::string> cache = {"POCL_CACHE_DIR=" + (dir / "cache").string()};
    StartupTiming t;
    t.measured = true;
    t.cold_ms = 1e3 * timed_ggx(one_sample, device, cache);
    std::vector<double> warm;
    for (int r = 0; r < warm_runs; ++r)
        warm.push_back(1e3 * timed_ggx(one_sample, device, cache));
    t.warm_ms = summarize(warm);
    fs::remove_all(dir);
    return t;
}

AppTimings measure_apps(const DeviceArguments& device, std::uint32_t count)
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
    t.sample_npy = median_of_runs(with_out(sample, "s.npy"), device, count, dir);
    t.npy_file_floor = file_write_floor(dir, count, 4 * sizeof(float));  // m and pdf_m
    t.histogram = median_of_runs({"histogram", "--method", "caps", "--no-png", "--out", (dir / "h").string()}, device,
                                 count, dir);
    t.histogram_device = recorded_device_ns(dir / "h.json", count);
    const std::uint32_t text_count = std::min<std::uint32_t>(count, 1u << 20);
    t.text_count = text_count;
    t.sample_csv = ns_per_sample(with_out(sample, "s.csv"), device, text_count);
    t.sample_ply = ns_per_sample(with_out({"sample", "--method", "caps", "--fields", "m", "--out"}, "s.ply"), device,
                                 text_count);
    fs::remove_all(dir);
    return t;
}

} // namespace ggxapp
