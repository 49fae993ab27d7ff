// kernel_ir.cpp - finding clang and compiling OpenCL C sources to LLVM IR
// text, in parallel, in a temporary directory.
#include "kernel_ir.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <unistd.h>

#include "child_process.hpp"

namespace fs = std::filesystem;

namespace ggxapp {

namespace {

// `name` in a folder of $PATH that holds it as an executable file; empty when none does.
std::string on_path(const std::string& name)
{
    const char* path = std::getenv("PATH");
    std::stringstream folders(path ? path : "");
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        const fs::path candidate = fs::path(folder.empty() ? "." : folder) / name;
        if (::access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate))
            return candidate.string();
    }
    return "";
}

// A fresh folder under the system's temporary directory, removed with its contents at scope exit.
struct ScratchFolder {
    fs::path path;
    ScratchFolder()
    {
        std::random_device random;
        for (int attempt = 0; attempt < 100 && path.empty(); ++attempt) {
            fs::path candidate = fs::temp_directory_path() / ("ggx-ir-" + std::to_string(random()));
            if (fs::create_directory(candidate))
                path = candidate;
        }
        if (path.empty())
            throw std::runtime_error("cannot create a folder under " + fs::temp_directory_path().string());
    }
    ~ScratchFolder()
    {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
};

std::vector<std::string> clang_arguments(const std::string& options, const std::string& source_file)
{
    std::vector<std::string> args = {"-x", "cl", "-cl-std=CL1.2", "-target", "spir64-unknown-unknown", "-O3",
                                     "-Xclang", "-finclude-default-header", "-emit-llvm", "-S", "-o", "-"};
    std::istringstream words(options);
    for (std::string word; words >> word;)
        args.push_back(word);
    args.push_back(source_file);
    return args;
}

std::string compile_one(const ClangTool& clang, const IrRequest& request, const fs::path& source_file)
{
    std::ofstream(source_file) << request.source;
    const std::vector<std::string> args = clang_arguments(request.options, source_file.string());
    ChildOutput result = run_child(clang.path, args, 120);  // stopped when it runs past 2 min
    if (!exited_ok(result.status))
        throw std::runtime_error("`" + command_text(clang.path, args) + "` " + describe_exit(result.status) + ": " +
                                 result.err.substr(0, 2000));
    return result.out;
}

} // namespace

ClangTool find_clang()
{
    if (const char* chosen = std::getenv("GGXCL_CLANG"); chosen && *chosen) {
        const std::string path = std::string(chosen).find('/') == std::string::npos ? on_path(chosen) : chosen;
        if (path.empty() || ::access(path.c_str(), X_OK) != 0)
            return {"", std::string("GGXCL_CLANG=") + chosen + " is not an executable file"};
        return {path, ""};
    }
    const std::string path = on_path("clang-15");
    if (path.empty())
        return {"", "clang-15 not found on PATH (set GGXCL_CLANG to a clang 15 or later)"};
    return {path, ""};
}

std::vector<std::string> compile_to_ir(const ClangTool& clang, const std::vector<IrRequest>& requests, int parallel)
{
    if (clang.path.empty())
        throw std::runtime_error("no clang: " + clang.unavailable);
    std::map<std::pair<std::string, std::string>, std::size_t> first_of;  // distinct requests
    std::vector<std::size_t> distinct;
    for (std::size_t r = 0; r < requests.size(); ++r)
        if (first_of.emplace(std::make_pair(requests[r].source, requests[r].options), r).second)
            distinct.push_back(r);
    ScratchFolder scratch;
    std::vector<std::string> ir(requests.size());
    std::vector<std::string> errors(requests.size());
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t k; (k = next++) < distinct.size();) {
            const std::size_t r = distinct[k];
            try {
                ir[r] = compile_one(clang, requests[r], scratch.path / ("program-" + std::to_string(r) + ".cl"));
            } catch (const std::exception& e) {
                errors[r] = e.what();
            }
        }
    };
    std::vector<std::thread> workers;
    for (int t = 0; t < std::max(1, parallel); ++t)
        workers.emplace_back(worker);
    for (std::thread& t : workers)
        t.join();
    for (const std::string& error : errors)
        if (!error.empty())
            throw std::runtime_error(error);
    for (std::size_t r = 0; r < requests.size(); ++r)
        ir[r] = ir[first_of.at({requests[r].source, requests[r].options})];
    return ir;
}

} // namespace ggxapp
