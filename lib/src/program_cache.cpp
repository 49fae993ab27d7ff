// program_cache.cpp - building and caching programs per (device, options).
#include "ggxcl/program_cache.hpp"

#include "ggxcl/error.hpp"
#include "ggxcl/kernel_sources.hpp"

namespace ggxcl {

namespace {
cl::Program build(const cl::Context& context, const cl::Device& device, const std::string& file,
                  const std::string& options)
{
    cl::Program program(context, kernel_source(file));
    try {
        program.build({device}, options.c_str());
    } catch (const cl::Error& e) {
        std::string log;
        try {
            log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
        } catch (const cl::Error&) {
            log = "(no build log available)";
        }
        throw BuildError(e.err(), device.getInfo<CL_DEVICE_NAME>(), options, log);
    }
    return program;
}
} // namespace

cl::Program ProgramCache::get(const cl::Device& device, const std::string& file, const std::string& options)
{
    std::lock_guard<std::mutex> lock(mutex_);
    auto key = std::make_pair(device(), file + "\n" + options);
    auto found = programs_.find(key);
    if (found != programs_.end())
        return found->second;
    cl::Program program = build(context_, device, file, options);
    programs_.emplace(key, program);
    return program;
}

std::size_t ProgramCache::size() const
{
    std::lock_guard<std::mutex> lock(mutex_);
    return programs_.size();
}

} // namespace ggxcl
