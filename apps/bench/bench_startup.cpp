// bench_startup.cpp - times child processes of this very binary.
#include "bench_startup.hpp"

#include <chrono>
#include <filesystem>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace ggxapp {

namespace {

namespace fs = std::filesystem;

// Wall-clock milliseconds of `ggx sample -n 1` with the kernel cache in `cache`.
double run_once(const fs::path& dir, const fs::path& cache, const DeviceArguments& device)
{
    std::vector<std::string> words = {"/proc/self/exe", "sample", "--method", "caps",
                                      "-n",             "1",      "--out",    (dir / "one.npy").string()};
    words.insert(words.end(), device.begin(), device.end());
    std::vector<std::string> env = {"POCL_CACHE_DIR=" + cache.string()};
    for (char** e = environ; *e; ++e)
        if (std::string(*e).rfind("POCL_CACHE_DIR=", 0) != 0)
            env.push_back(*e);
    std::vector<char*> argv, envp;
    for (std::string& w : words) argv.push_back(w.data());
    for (std::string& e : env) envp.push_back(e.data());
    argv.push_back(nullptr);
    envp.push_back(nullptr);
    auto start = std::chrono::steady_clock::now();
    pid_t pid;
    int status = -1;
    if (::posix_spawn(&pid, "/proc/self/exe", nullptr, nullptr, argv.data(), envp.data()) != 0)
        throw std::runtime_error("cannot start ggx for the start-up timing");
    ::waitpid(pid, &status, 0);
    std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("`ggx sample -n 1` failed during the start-up timing");
    return elapsed.count();
}

} // namespace

StartupTiming measure_startup(const DeviceArguments& device, int warm_runs)
{
    fs::path dir = fs::temp_directory_path() / ("ggx-startup-" + std::to_string(::getpid()));
    fs::create_directories(dir / "cache");
    StartupTiming t;
    t.measured = true;
    t.cold_ms = run_once(dir, dir / "cache", device);
    std::vector<double> warm;
    for (int r = 0; r < warm_runs; ++r)
        warm.push_back(run_once(dir, dir / "cache", device));
    t.warm_ms = summarize(warm);
    fs::remove_all(dir);
    return t;
}

} // namespace ggxapp
