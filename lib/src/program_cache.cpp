// program_cache.cpp - building and caching programs per (device, options),
// in memory and (as binaries) on disk.
#include "program_cache.hpp"

#include "build_program.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/kernel_sources.hpp"

namespace ggxcl {

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

// Called with mutex_ held.
ProgramCache::Variant& ProgramCache::variant(const cl::Device& device, const std::string& file,
                                             const std::string& options)
{
    auto key = std::make_pair(device(), file + "\n" + options);
    auto found = programs_.find(key);
    if (found != programs_.end())
        return found->second;
    bool from_disk = false;
    // The kernels are OpenCL C 1.2 and use no extension: every device builds them.
    cl::Program program =
        detail::build_program(context_, device, kernel_source(file), options + " -cl-std=CL1.2", true, &from_disk);
    loaded_from_disk_ += from_disk ? 1 : 0;
    return programs_.emplace(key, Variant{program, {}}).first->second;
}

cl::Program ProgramCache::get(const cl::Device& device, const std::string& file, const std::string& options)
{
    std::lock_guard<std::mutex> lock(mutex_);
    return variant(device, file, options).program;
}

KernelLease ProgramCache::kernel(const cl::Device& device, const std::string& file, const std::string& options,
                                 const std::string& name)
{
    std::unique_lock<std::mutex> lock(mutex_);
    Variant& v = variant(device, file, options);
    std::vector<cl::Kernel>* idle = &v.idle[name];
    if (!idle->empty()) {
        cl::Kernel k = std::move(idle->back());
        idle->pop_back();
        return KernelLease(this, idle, std::move(k));
    }
    cl::Program program = v.program;
    lock.unlock();
    return KernelLease(this, idle, cl::Kernel(program, name.c_str()));
}

void ProgramCache::give_back(std::vector<cl::Kernel>* idle, cl::Kernel kernel)
{
    std::lock_guard<std::mutex> lock(mutex_);
    idle->push_back(std::move(kernel));
}

KernelLease::~KernelLease()
{
    if (cache_ && kernel_() != nullptr)
        cache_->give_back(idle_, std::move(kernel_));
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
