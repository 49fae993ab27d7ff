// device_faults.hpp - what the runtime does when a device runs out of
// memory or is lost: device buffers and launches go through here, where the
// faults that tests inject (GGXCL_INJECT_FAULT, fault_injection.hpp) strike.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "ggxcl/opencl.hpp"

namespace ggxcl::detail {

// A device buffer; throws cl::Error as clCreateBuffer would.
cl::Buffer device_buffer(const cl::Context& context, cl_mem_flags flags, std::size_t bytes);

// Called before every kernel launch; throws cl::Error when a lost device is injected.
void before_launch();

// CL error codes that mean the device (or the host) ran out of memory.
bool is_out_of_memory(int code);

// CL error codes that mean the device stopped working under us (a lost
// device gives CL_DEVICE_NOT_AVAILABLE, or invalidates its queue).
bool is_device_lost(int code);

// Runs `pass(capacity)` until it completes.  A pass resumes from where the
// previous one stopped (it keeps its own position); when a pass fails for
// lack of memory, capacity is halved (not below `smallest`) and counted in
// `retries`, and the next pass runs with the smaller capacity, a multiple
// of `granule`.  At `smallest` the out-of-memory error goes to the caller,
// as a ClError that says so.
void retry_with_smaller_chunks(std::uint64_t& capacity, std::uint64_t smallest, std::atomic<std::uint64_t>& retries,
                               const std::function<void(std::uint64_t capacity)>& pass, std::uint64_t granule = 1);

} // namespace ggxcl::detail
