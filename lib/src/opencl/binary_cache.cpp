// binary_cache.cpp - the on-disk store of program binaries (binary_cache.hpp).
#include "binary_cache.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

#include "cache_roots.hpp"
#include "device_quirks.hpp"
#include "ggxcl/version.hpp"

namespace ggxcl::detail {

namespace {

namespace fs = std::filesystem;

constexpr char magic[] = "ggxcl-program-binary-1\n";
constexpr std::uintmax_t size_limit = 512ull << 20;

// The directory, or an empty path when the cache is off.
fs::path cache_dir()
{
    if (const char* chosen = std::getenv("GGXCL_PROGRAM_CACHE"); chosen && *chosen) {
        const std::string value = chosen;
        return value == "off" || value == "0" ? fs::path() : fs::path(value);
    }
    std::vector<fs::path> roots = cache_roots();
    return roots.empty() ? fs::path() : roots.front() / "programs";
}

std::string file_name(const std::string& key)
{
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.bin", static_cast<unsigned long long>(fnv1a(key)));
    return name;
}

// Removes the oldest files until the directory holds at most 3/4 of the limit.
void keep_under_limit(const fs::path& dir)
{
    std::vector<std::pair<fs::file_time_type, fs::path>> files;
    std::uintmax_t total = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
        if (!entry.is_regular_file())
            continue;
        total += entry.file_size();
        files.emplace_back(entry.last_write_time(), entry.path());
    }
    if (total <= size_limit)
        return;
    std::sort(files.begin(), files.end());
    for (const auto& [time, path] : files) {
        if (total <= size_limit / 4 * 3)
            break;
        std::error_code ignored;
        std::uintmax_t size = fs::file_size(path, ignored);
        if (fs::remove(path, ignored))
            total -= size;
    }
}

} // namespace

bool binary_cache_applies(const cl::Device& device)
{
    const char* chosen = std::getenv("GGXCL_PROGRAM_CACHE");
    if (chosen && *chosen)
        return !cache_dir().empty();
    return !platform_caches_programs(device);
}

std::string binary_cache_key(const cl::Device& device, const std::string& source, const std::string& options)
{
    cl::Platform platform(device.getInfo<CL_DEVICE_PLATFORM>());
    std::string key = std::string("ggxcl ") + version() + "\n";
    key += platform.getInfo<CL_PLATFORM_NAME>() + "\n" + platform.getInfo<CL_PLATFORM_VERSION>() + "\n";
    key += device.getInfo<CL_DEVICE_NAME>() + "\n" + device.getInfo<CL_DEVICE_VERSION>() + "\n";
    key += device.getInfo<CL_DRIVER_VERSION>() + "\n" + options + "\n" + source;
    return key;
}

bool load_program_binary(const std::string& key, std::vector<unsigned char>& binary)
{
    const fs::path dir = cache_dir();
    if (dir.empty())
        return false;
    std::ifstream in(dir / file_name(key), std::ios::binary);
    if (!in)
        return false;
    std::vector<char> stored_key(sizeof magic - 1 + key.size());
    std::uint64_t stored_size = 0;
    if (!in.read(stored_key.data(), stored_key.size()) ||
        std::string(stored_key.begin(), stored_key.end()) != magic + key)
        return false;
    if (!in.read(reinterpret_cast<char*>(&stored_size), sizeof stored_size) || stored_size == 0 ||
        stored_size > size_limit)
        return false;
    binary.resize(stored_size);
    std::uint64_t stored_hash = 0;
    return in.read(reinterpret_cast<char*>(binary.data()), std::streamsize(stored_size)) &&
           in.read(reinterpret_cast<char*>(&stored_hash), sizeof stored_hash) && stored_hash == fnv1a(binary);
}

void store_program_binary(const std::string& key, const std::vector<unsigned char>& binary)
{
    const fs::path dir = cache_dir();
    if (dir.empty() || binary.empty())
        return;
    std::error_code failed;
    fs::create_directories(dir, failed);
    if (failed)
        return;
    const fs::path target = dir / file_name(key);
    fs::path staging = target;
    static std::atomic<unsigned> stores{0};  // threads of one process stage apart
    staging += ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(stores++);
    {
        std::ofstream out(staging, std::ios::binary | std::ios::trunc);
        const std::uint64_t size = binary.size();
        out << magic << key;
        out.write(reinterpret_cast<const char*>(&size), sizeof size);
        const std::uint64_t hash = fnv1a(binary);
        out.write(reinterpret_cast<const char*>(binary.data()), std::streamsize(size));
        out.write(reinterpret_cast<const char*>(&hash), sizeof hash);
        if (!out.flush()) {
            out.close();
            fs::remove(staging, failed);
            return;
        }
    }
    fs::rename(staging, target, failed);
    if (failed) {
        fs::remove(staging, failed);
        return;
    }
    try {
        keep_under_limit(dir);
    } catch (const fs::filesystem_error&) {
        // another process removed a file while we looked: the next store tries again
    }
}

} // namespace ggxcl::detail
