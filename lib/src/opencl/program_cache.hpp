// program_cache.hpp - OpenCL programs built from an embedded source, once
// per (device, build options) and kept for the life of the cache.  A failed
// build throws BuildError with the CL error name, the options and the log.
// On platforms that keep no compiled programs themselves (Mesa rusticl,
// Oclgrind; PoCL and NVIDIA do), binaries are also kept on disk, so later
// processes on the same device and driver skip the compiler: in
// ~/.cache/ggxcl/programs (or $XDG_CACHE_HOME/ggxcl/programs).
// GGXCL_PROGRAM_CACHE=DIR uses DIR for every platform; "off" turns it off.
//
// Kernel objects are per thread: a cl::Kernel's arguments are not safe to
// set from two threads, so each thread keeps its own kernel per program and
// name and leases it to itself, with no lock once the thread has used the
// variant (the program map's mutex is taken only on a thread's first use of
// a variant, and for builds).  A thread's kernels of a cache that has gone
// are released at its next lease, and all of them when the thread ends.
// Every Sampler on one context shares that context's cache.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "ggxcl/opencl.hpp"

namespace ggxcl {

// A kernel lent to one caller on the calling thread until the lease ends:
// the thread's own kernel of that name, or (when the thread already holds
// that one) a kernel of the lease's own.
class KernelLease {
public:
    explicit KernelLease(cl::Kernel own) : own_(std::move(own)), kernel_(&own_), busy_(nullptr) {}
    KernelLease(cl::Kernel* threads, bool* busy) : kernel_(threads), busy_(busy) { *busy_ = true; }
    KernelLease(KernelLease&& other) noexcept
        : own_(std::move(other.own_)), kernel_(other.busy_ ? other.kernel_ : &own_),
          busy_(std::exchange(other.busy_, nullptr))
    {
    }
    KernelLease(const KernelLease&) = delete;
    KernelLease& operator=(const KernelLease&) = delete;
    KernelLease& operator=(KernelLease&&) = delete;
    ~KernelLease()
    {
        if (busy_)
            *busy_ = false;
    }

    cl::Kernel& operator*() { return *kernel_; }
    cl::Kernel* operator->() { return kernel_; }

private:
    cl::Kernel own_;     // a kernel of the lease's own, when the thread's was busy
    cl::Kernel* kernel_; // &own_ or the thread's kernel
    bool* busy_;         // the thread's flag for its kernel, null for a kernel of the lease's own
};

class ProgramCache {
public:
    explicit ProgramCache(cl::Context context);
    ~ProgramCache();
    ProgramCache(const ProgramCache&) = delete;
    ProgramCache& operator=(const ProgramCache&) = delete;

    // The cache every Sampler on `context` shares, created on first use and
    // kept while a Sampler holds it.
    static std::shared_ptr<ProgramCache> for_context(const cl::Context& context);

    // The program of embedded file `file` built for `device` with `options`.
    cl::Program get(const cl::Device& device, const std::string& file, const std::string& options);

    // Kernel `name` of that program, lent to the calling thread until the lease ends.
    KernelLease kernel(const cl::Device& device, const std::string& file, const std::string& options,
                       const std::string& name);

    // Number of distinct programs built so far.
    std::size_t size() const;
    // How many of them came from binaries on disk rather than the compiler.
    std::size_t loaded_from_disk() const;

private:
    cl::Context context_;
    const std::uint64_t serial_;  // unique in the process: names this cache in the threads' kernel tables
    mutable std::mutex mutex_;
    std::map<std::pair<cl_device_id, std::string>, cl::Program> programs_;
    std::size_t loaded_from_disk_ = 0;
};

} // namespace ggxcl
