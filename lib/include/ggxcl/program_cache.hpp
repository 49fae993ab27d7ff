// program_cache.hpp - OpenCL programs built from an embedded source, once
// per (device, build options) and kept for the life of the cache.  A failed
// build throws BuildError with the CL error name, the options and the log.
// On platforms that keep no compiled programs themselves (Mesa rusticl,
// Oclgrind; PoCL and NVIDIA do), binaries are also kept on disk, so later
// processes on the same device and driver skip the compiler: in
// ~/.cache/ggxcl/programs (or $XDG_CACHE_HOME/ggxcl/programs).
// GGXCL_PROGRAM_CACHE=DIR uses DIR for every platform; "off" turns it off.
#pragma once

#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "ggxcl/opencl.hpp"

namespace ggxcl {

class ProgramCache {
public:
    explicit ProgramCache(cl::Context context) : context_(std::move(context)) {}

    // The program of embedded file `file` built for `device` with `options`.
    cl::Program get(const cl::Device& device, const std::string& file, const std::string& options);

    // Number of distinct programs built so far.
    std::size_t size() const;
    // How many of them came from binaries on disk rather than the compiler.
    std::size_t loaded_from_disk() const;

private:
    cl::Context context_;
    mutable std::mutex mutex_;
    std::map<std::pair<cl_device_id, std::string>, cl::Program> programs_;
    std::size_t loaded_from_disk_ = 0;
};

} // namespace ggxcl
