// device_faults.cpp - out-of-memory retries, lost-device codes and the
// fault injection of GGXCL_INJECT_FAULT.
#include "device_faults.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>

#include "ggxcl/error.hpp"

namespace ggxcl::detail {

namespace {

struct InjectedFault {
    std::uint64_t alloc_above = 0;  // 0: no allocation fault
    std::uint64_t lost_after = 0;
    bool lost = false;              // lost_after is set
};

std::uint64_t parse_amount(const std::string& spec, const std::string& text)
{
    std::size_t used = 0;
    unsigned long long value = 0;
    try {
        value = std::stoull(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || text[0] == '-')
        throw InvalidArgument("GGXCL_INJECT_FAULT", spec, "alloc-above=BYTES or lost-after=LAUNCHES (whole numbers)");
    return value;
}

InjectedFault parse_fault(const std::string& spec)
{
    InjectedFault fault;
    const std::string alloc = "alloc-above=", lost = "lost-after=";
    if (spec.rfind(alloc, 0) == 0) {
        fault.alloc_above = parse_amount(spec, spec.substr(alloc.size()));
    } else if (spec.rfind(lost, 0) == 0) {
        fault.lost_after = parse_amount(spec, spec.substr(lost.size()));
        fault.lost = true;
    } else if (!spec.empty()) {
        parse_amount(spec, "");  // throws, naming the forms allowed
    }
    return fault;
}

// The fault the environment asks for now, and the launches counted since it
// was set (this call's, with count_launch, included).  The value is parsed
// when it changes; a malformed one is refused on every call.  While the
// variable has never been set, a launch costs one getenv and no lock.
InjectedFault current_fault(bool count_launch, std::uint64_t& launches_before)
{
    static std::mutex mutex;
    static std::atomic<bool> ever_set{false};
    static std::string last_spec;
    static std::exception_ptr refused;  // the InvalidArgument of a malformed value
    static InjectedFault fault;
    static std::uint64_t launches = 0;
    const char* env = std::getenv("GGXCL_INJECT_FAULT");
    if (env == nullptr && !ever_set.load(std::memory_order_acquire)) {
        launches_before = 0;
        return {};
    }
    ever_set.store(true, std::memory_order_release);
    std::string spec = env ? env : "";
    std::lock_guard<std::mutex> lock(mutex);
    if (spec != last_spec) {
        last_spec = spec;
        launches = 0;
        fault = {};
        refused = nullptr;
        try {
            fault = parse_fault(spec);
        } catch (const InvalidArgument&) {
            refused = std::current_exception();
        }
    }
    if (refused)
        std::rethrow_exception(refused);
    launches_before = launches;
    launches += count_launch ? 1 : 0;
    return fault;
}

} // namespace

cl::Buffer device_buffer(const cl::Context& context, cl_mem_flags flags, std::size_t bytes)
{
    std::uint64_t launches = 0;
    InjectedFault fault = current_fault(false, launches);
    if (fault.alloc_above != 0 && bytes > fault.alloc_above)
        throw cl::Error(CL_MEM_OBJECT_ALLOCATION_FAILURE, "clCreateBuffer (GGXCL_INJECT_FAULT)");
    return cl::Buffer(context, flags, bytes);
}

void before_launch()
{
    std::uint64_t launch = 0;
    InjectedFault fault = current_fault(true, launch);
    if (fault.lost && launch >= fault.lost_after)
        throw cl::Error(CL_DEVICE_NOT_AVAILABLE, "clEnqueueNDRangeKernel (GGXCL_INJECT_FAULT)");
}

bool is_out_of_memory(int code)
{
    return code == CL_MEM_OBJECT_ALLOCATION_FAILURE || code == CL_OUT_OF_RESOURCES || code == CL_OUT_OF_HOST_MEMORY;
}

bool is_device_lost(int code)
{
    return code == CL_DEVICE_NOT_AVAILABLE || code == CL_INVALID_COMMAND_QUEUE;
}

void retry_with_smaller_chunks(std::uint64_t& capacity, std::uint64_t smallest, std::uint64_t& retries,
                               const std::function<void(std::uint64_t capacity)>& pass, std::uint64_t granule)
{
    for (;;) {
        int code = CL_SUCCESS;
        try {
            pass(capacity);
            return;
        } catch (const cl::Error& e) {
            if (!is_out_of_memory(e.err()))
                throw;
            code = e.err();
        } catch (const ClError& e) {
            if (!is_out_of_memory(e.code()))
                throw;
            code = e.code();
        }
        if (capacity <= smallest)
            throw ClError("running chunks of " + std::to_string(capacity) + " samples (the smallest tried)", code);
        capacity = std::max(smallest, capacity / 2 / granule * granule);
        ++retries;
    }
}

} // namespace ggxcl::detail
