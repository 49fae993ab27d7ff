// program_cache.cpp - building and caching programs per (device, options),
// in memory and (as binaries) on disk, and each thread's own kernels.
#include "program_cache.hpp"

#include <atomic>
#include <set>
#include <unordered_map>

#include "build_program.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/kernel_sources.hpp"
#include "ggxcl/user_sampler.hpp"

namespace ggxcl {

namespace {

// The serials of the caches alive, and how many caches have gone: a thread
// looks at the set only when that count changed since its last lease.
std::atomic<std::uint64_t> next_serial{1}, caches_gone{0};
std::mutex live_mutex;
std::set<std::uint64_t> live_serials;

// One thread's kernels, by cache serial, device, file, options and name.
struct ThreadKernels {
    struct Entry {
        std::uint64_t serial;
        cl::Kernel kernel;
        bool busy = false;
    };
    std::unordered_map<std::string, Entry> entries;  // node-based: an Entry stays put while leased
    std::uint64_t gone_seen = 0;

    // Releases the kernels of caches that have gone (their programs and contexts with them).
    void forget_gone_caches()
    {
        const std::uint64_t gone = caches_gone.load(std::memory_order_acquire);
        if (gone == gone_seen)
            return;
        gone_seen = gone;
        std::lock_guard<std::mutex> lock(live_mutex);
        for (auto it = entries.begin(); it != entries.end();)
            it = live_serials.count(it->second.serial) || it->second.busy ? std::next(it) : entries.erase(it);
    }
};

thread_local ThreadKernels thread_kernels;

std::string kernel_key(std::uint64_t serial, cl_device_id device, const std::string& file, const std::string& options,
                       const std::string& name)
{
    return std::to_string(serial) + '\n' + std::to_string(reinterpret_cast<std::uintptr_t>(device)) + '\n' + file +
           '\n' + name + '\n' + options;
}

} // namespace

ProgramCache::ProgramCache(cl::Context context) : context_(std::move(context)), serial_(next_serial++)
{
    std::lock_guard<std::mutex> lock(live_mutex);
    live_serials.insert(serial_);
}

ProgramCache::~ProgramCache()
{
    std::lock_guard<std::mutex> lock(live_mutex);
    live_serials.erase(serial_);
    caches_gone.fetch_add(1, std::memory_order_release);
}

std::shared_ptr<ProgramCache> ProgramCache::for_context(const cl::Context& context)
{
    static std::mutex mutex;
    static std::map<cl_context, std::weak_ptr<ProgramCache>> caches;
    std::lock_guard<std::mutex> lock(mutex);
    for (auto it = caches.begin(); it != caches.end();)  // forget the caches of released contexts
        it = it->second.expired() ? caches.erase(it) : std::next(it);
    std::shared_ptr<ProgramCache> cache = caches[context()].lock();
    if (!cache) {
        cache = std::make_shared<ProgramCache>(context);
        caches[context()] = cache;
    }
    return cache;
}

cl::Program ProgramCache::get(const cl::Device& device, const std::string& file, const std::string& options)
{
    std::lock_guard<std::mutex> lock(mutex_);
    auto key = std::make_pair(device(), file + "\n" + options);
    auto found = programs_.find(key);
    if (found != programs_.end())
        return found->second;
    bool from_disk = false;
    // The kernels are OpenCL C 1.2 and use no extension: every device builds them.
    cl::Program program;
    try {
        program = detail::build_program(context_, device, program_source(file, options),
                                        options + " -cl-std=CL1.2", true, &from_disk);
    } catch (const BuildError& error) {
        if (options.find("-DGGX_USER_SAMPLER=1") == std::string::npos)
            throw;
        throw BuildError(error.code(), device.getInfo<CL_DEVICE_NAME>(), options + " -cl-std=CL1.2", error.log(),
                         user_build_summary(error.log()));
    }
    loaded_from_disk_ += from_disk ? 1 : 0;
    return programs_.emplace(key, program).first->second;
}

KernelLease ProgramCache::kernel(const cl::Device& device, const std::string& file, const std::string& options,
                                 const std::string& name)
{
    ThreadKernels& mine = thread_kernels;
    mine.forget_gone_caches();
    const std::string key = kernel_key(serial_, device(), file, options, name);
    auto found = mine.entries.find(key);
    if (found != mine.entries.end() && !found->second.busy)
        return KernelLease(&found->second.kernel, &found->second.busy);
    cl::Kernel fresh(get(device, file, options), name.c_str());
    if (found != mine.entries.end())  // this thread holds its kernel already (a lease within a lease)
        return KernelLease(std::move(fresh));
    ThreadKernels::Entry& entry = mine.entries[key];
    entry = {serial_, std::move(fresh), false};
    return KernelLease(&entry.kernel, &entry.busy);
}

std::size_t ProgramCache::loaded_from_disk() const
{
    std::lock_guard<std::mutex> lock(mutex_);
    return loaded_from_disk_;
}

std::size_t ProgramCache::size() const
{
    std::lock_guard<std::mutex> lock(mutex_);
    return programs_.size();
}

} // namespace ggxcl
