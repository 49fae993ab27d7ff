// device_header_dir.cpp - a directory whose device headers are the ones
// embedded in this library (device_include_dir): the environment's choice,
// else a copy of the embedded text written once per version to a cache.
#include "ggxcl/user_kernels.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <vector>
#include <unistd.h>

#include "cache_roots.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/kernel_sources.hpp"
#include "ggxcl/version.hpp"

namespace ggxcl {

namespace {

namespace fs = std::filesystem;

// The whole file, or false when it cannot be read.
bool read_text(const fs::path& path, std::string& text)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return false;
    std::ostringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
    return true;
}

// Whether `dir` holds every embedded header with the embedded text.
bool matches_embedded(const fs::path& dir)
{
    for (const std::string& name : kernel_files()) {
        std::string text;
        if (!read_text(dir / name, text) || text != kernel_source(name))
            return false;
    }
    return true;
}

// A name for this version's headers: version and a 64-bit FNV-1a hash of
// every embedded file's name and text.
std::string content_id()
{
    std::uint64_t hash = detail::fnv1a(std::string());
    for (const std::string& name : kernel_files())
        for (const std::string* part : {&name, &kernel_source(name)})
            hash = detail::fnv1a(*part + '\0', hash);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return std::string(version()) + "-" + hex;
}

// Writes the embedded headers into a fresh directory next to `target`, then
// renames it to `target`; a concurrent writer that wins leaves its copy.
void publish_embedded_headers(const fs::path& target)
{
    fs::create_directories(target.parent_path());
    fs::path staging = target;
    staging += ".tmp-" + std::to_string(getpid());
    fs::remove_all(staging);
    write_device_headers(staging.string());
    std::error_code renamed;
    fs::rename(staging, target, renamed);
    if (renamed)
        fs::remove_all(staging);  // another process put a copy there first
}

// A matching copy of the embedded headers under the first usable cache root.
std::string cached_copy()
{
    static std::mutex writing;  // one writer per process; rename() settles races between processes
    std::lock_guard<std::mutex> lock(writing);
    std::string failures;
    for (const fs::path& root : detail::cache_roots()) {
        const fs::path target = root / ("device-headers-" + content_id());
        try {
            if (!matches_embedded(target)) {
                fs::remove_all(target);
                publish_embedded_headers(target);
            }
            if (matches_embedded(target))
                return target.string();
            failures += "\n  " + target.string() + ": written but does not match";
        } catch (const std::exception& e) {
            failures += "\n  " + target.string() + ": " + e.what();
        }
    }
    throw Error("cannot write the device headers anywhere:" + failures +
                "\nset GGXCL_DEVICE_INCLUDE_DIR, or prepend kernel_source(\"ggx_samplers.h\") to your source");
}

} // namespace

std::string device_include_dir()
{
    if (const char* chosen = std::getenv("GGXCL_DEVICE_INCLUDE_DIR"); chosen && *chosen) {
        if (!fs::is_regular_file(fs::path(chosen) / "ggx_samplers.h"))
            throw InvalidArgument("GGXCL_DEVICE_INCLUDE_DIR", chosen, "a directory holding ggx_samplers.h");
        return chosen;
    }
    return cached_copy();
}

void write_device_headers(const std::string& directory)
{
    fs::create_directories(directory);
    for (const std::string& name : kernel_files()) {
        std::ofstream out(fs::path(directory) / name, std::ios::binary);
        out << kernel_source(name);
        if (!out.flush())
            throw Error("cannot write the device header " + (fs::path(directory) / name).string());
    }
}

} // namespace ggxcl
