// program_cache.cpp - building and caching programs per (device, options),
// in memory and (as binaries) on disk.
#include "ggxcl/program_cache.hpp"

#include "build_program.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/kernel_sources.hpp"

namespace ggxcl {

cl::Program ProgramCache::get(const cl::Device& device, const std::string& file, const std::string& options)
{
    std::lock_guard<std::mutex> lock(mutex_);
    auto key = std::make_pair(device(), file + "\n" + options);
    auto found = programs_.find(key);
    if (found != programs_.end())
        return found->second;
    bool from_disk = false;
    // The kernels are OpenCL C 1.2 and use no extension: every device builds them.
    cl::Program program =
        detail::build_program(context_, device, kernel_source(file), options + " -cl-std=CL1.2", true, &from_disk);
    loaded_from_disk_ += from_disk ? 1 : 0;
    programs_.emplace(key, program);
    return program;
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
