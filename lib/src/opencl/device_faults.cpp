// device_faults.cpp - out-of-memory retries, lost-device codes, and where
// the faults of GGXCL_INJECT_FAULT (fault_injection.hpp) strike.
#include "device_faults.hpp"

#include <algorithm>
#include <string>

#include "fault_injection.hpp"
#include "ggxcl/error.hpp"

namespace ggxcl::detail {

cl::Buffer device_buffer(const cl::Context& context, cl_mem_flags flags, std::size_t bytes)
{
    std::uint64_t launches = 0;
    InjectedFault fault = injected_fault(false, launches);
    if (fault.alloc_above != 0 && bytes > fault.alloc_above)
        throw cl::Error(CL_MEM_OBJECT_ALLOCATION_FAILURE, "clCreateBuffer (GGXCL_INJECT_FAULT)");
    return cl::Buffer(context, flags, bytes);
}

void before_launch()
{
    std::uint64_t launch = 0;
    InjectedFault fault = injected_fault(true, launch);
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

void retry_with_smaller_chunks(std::uint64_t& capacity, std::uint64_t smallest, std::atomic<std::uint64_t>& retries,
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
