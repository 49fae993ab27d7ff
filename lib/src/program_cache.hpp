// program_cache.hpp - OpenCL programs built from an embedded source, once
// per (device, build options) and kept for the life of the cache.  A failed
// build throws BuildError with the CL error name, the options and the log.
// On platforms that keep no compiled programs themselves (Mesa rusticl,
// Oclgrind; PoCL and NVIDIA do), binaries are also kept on disk, so later
// processes on the same device and driver skip the compiler: in
// ~/.cache/ggxcl/programs (or $XDG_CACHE_HOME/ggxcl/programs).
// GGXCL_PROGRAM_CACHE=DIR uses DIR for every platform; "off" turns it off.
//
// Kernel objects are kept too, per program and kernel name, and lent out
// one caller at a time (a cl::Kernel's arguments are not safe to set from
// two threads): a lease takes an idle kernel or creates one, and gives it
// back when it goes out of scope, after the launch has captured its
// arguments.  Every Sampler on one context shares that context's cache.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "ggxcl/opencl.hpp"

namespace ggxcl {

class ProgramCache;

// A kernel lent by a ProgramCache to one caller until the lease ends.
class KernelLease {
public:
    KernelLease(ProgramCache* cache, std::vector<cl::Kernel>* idle, cl::Kernel kernel)
        : cache_(cache), idle_(idle), kernel_(std::move(kernel)) {}
    KernelLease(KernelLease&& other) noexcept
        : cache_(std::exchange(other.cache_, nullptr)), idle_(other.idle_), kernel_(std::move(other.kernel_)) {}
    KernelLease(const KernelLease&) = delete;
    KernelLease& operator=(const KernelLease&) = delete;
    KernelLease& operator=(KernelLease&&) = delete;
    ~KernelLease();

    cl::Kernel& operator*() { return kernel_; }
    cl::Kernel* operator->() { return &kernel_; }

private:
    ProgramCache* cache_;
    std::vector<cl::Kernel>* idle_;
    cl::Kernel kernel_;
};

class ProgramCache {
public:
    explicit ProgramCache(cl::Context context) : context_(std::move(context)) {}

    // The cache every Sampler on `context` shares, created on first use and
    // kept while a Sampler holds it.
    static std::shared_ptr<ProgramCache> for_context(const cl::Context& context);

    // The program of embedded file `file` built for `device` with `options`.
    cl::Program get(const cl::Device& device, const std::string& file, const std::string& options);

    // Kernel `name` of that program, lent until the lease ends.
    KernelLease kernel(const cl::Device& device, const std::string& file, const std::string& options,
                       const std::string& name);

    // Number of distinct programs built so far.
    std::size_t size() const;
    // How many of them came from binaries on disk rather than the compiler.
    std::size_t loaded_from_disk() const;

private:
    friend class KernelLease;
    struct Variant {
        cl::Program program;
        std::map<std::string, std::vector<cl::Kernel>> idle;  // by kernel name
    };
    Variant& variant(const cl::Device& device, const std::string& file, const std::string& options);
    void give_back(std::vector<cl::Kernel>* idle, cl::Kernel kernel);

    cl::Context context_;
    mutable std::mutex mutex_;
    std::map<std::pair<cl_device_id, std::string>, Variant> programs_;  // std::map: stable addresses
    std::size_t loaded_from_disk_ = 0;
};

} // namespace ggxcl
