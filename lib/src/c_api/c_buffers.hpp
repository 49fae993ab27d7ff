// c_buffers.hpp - the caller's cl_mem buffers at offsets (in floats), as
// the buffers a launch of the C++ API takes, whose planes start at 0: the
// buffer itself at offset 0; a sub-buffer where the offset meets the
// device's base address alignment; else a scratch buffer, filled from the
// caller's before the kernel (inputs) or copied into it after (outputs),
// plane by plane so that what lies between the planes stays untouched.  The
// copies are chained by events to the caller's wait list and the kernel.
#pragma once

#include <cstdint>
#include <vector>

#include "ggxcl/ggxcl.h"
#include "ggxcl/opencl.hpp"

namespace ggxcl::capi {

class PlacedBuffers {
public:
    // For one call on `context`; `align_bytes` is the device's base address alignment.
    PlacedBuffers(const cl::Context& context, std::size_t align_bytes) : context_(context), align_bytes_(align_bytes) {}

    // The buffer the kernel reads (input) or writes (output) for `buffer`:
    // `planes` planes of `count` floats, `stride` apart (0: count); a default
    // buffer when buffer.mem is NULL.  Throws InvalidArgument naming
    // `parameter` when the caller's buffer is too small.
    cl::Buffer input(const ggxcl_buffer& buffer, const char* parameter, int planes, std::uint64_t count,
                     std::uint64_t stride);
    cl::Buffer output(const ggxcl_buffer& buffer, const char* parameter, int planes, std::uint64_t count,
                      std::uint64_t stride);

    // Enqueues the input copies after `wait` and returns what the kernel waits for.
    std::vector<cl::Event> before_kernel(cl::CommandQueue& queue, const std::vector<cl::Event>& wait);
    // Enqueues the output copies after `kernel` and returns the event of the whole call.
    cl::Event after_kernel(cl::CommandQueue& queue, const cl::Event& kernel);

private:
    struct PlaneCopies {
        cl::Buffer from, to;
        std::size_t from_offset, to_offset;  // floats
        int planes;
        std::uint64_t count, stride;         // floats per plane, floats between planes
    };
    cl::Buffer place(const ggxcl_buffer& buffer, const char* parameter, int planes, std::uint64_t count,
                     std::uint64_t stride, bool is_input);
    static std::vector<cl::Event> enqueue_copies(cl::CommandQueue& queue, const std::vector<PlaneCopies>& copies,
                                                 const std::vector<cl::Event>& wait);

    cl::Context context_;
    std::size_t align_bytes_;
    std::vector<PlaneCopies> in_copies_, out_copies_;
};

// CL_DEVICE_MEM_BASE_ADDR_ALIGN in bytes: where a sub-buffer may begin.
std::size_t base_address_alignment(const cl::Device& device);

// The caller's wait list as events (retained), and an event handed to the caller (retained for it).
std::vector<cl::Event> wait_list(cl_uint count, const cl_event* events);
void hand_over(const cl::Event& event, cl_event* out);

} // namespace ggxcl::capi
