// c_buffers.cpp - the caller's buffers at offsets: directly, as sub-buffers
// or through scratch buffers and per-plane copies (c_buffers.hpp).
#include "c_api/c_buffers.hpp"

#include <string>

#include "ggxcl/error.hpp"

namespace ggxcl::capi {

std::size_t base_address_alignment(const cl::Device& device)
{
    const std::size_t bytes = device.getInfo<CL_DEVICE_MEM_BASE_ADDR_ALIGN>() / 8;  // reported in bits
    return bytes == 0 ? 1 : bytes;
}

cl::Buffer PlacedBuffers::input(const ggxcl_buffer& buffer, const char* parameter, int planes, std::uint64_t count,
                                 std::uint64_t stride)
{
    return place(buffer, parameter, planes, count, stride, true);
}

cl::Buffer PlacedBuffers::output(const ggxcl_buffer& buffer, const char* parameter, int planes, std::uint64_t count,
                                  std::uint64_t stride)
{
    return place(buffer, parameter, planes, count, stride, false);
}

cl::Buffer PlacedBuffers::place(const ggxcl_buffer& buffer, const char* parameter, int planes, std::uint64_t count,
                                std::uint64_t stride, bool is_input)
{
    if (!buffer.mem)
        return {};
    if (stride == 0)
        stride = count;
    cl::Buffer caller(buffer.mem, true);
    // planes * stride floats from the offset, as the C++ API asks of its buffers.
    const std::size_t span = static_cast<std::size_t>(planes * stride);
    const std::size_t size = caller.getInfo<CL_MEM_SIZE>() / sizeof(float);
    if (buffer.offset > size || size - buffer.offset < span)
        throw InvalidArgument(parameter, "a buffer of " + std::to_string(size) + " floats with offset " +
                                             std::to_string(buffer.offset),
                              "offset + " + std::to_string(span) + " floats (" + std::to_string(planes) +
                                  " plane(s) of stride " + std::to_string(stride) + ") within the buffer");
    if (buffer.offset == 0 || count == 0)
        return caller;
    const std::size_t origin = buffer.offset * sizeof(float);
    if (origin % align_bytes_ == 0 && caller.getInfo<CL_MEM_ASSOCIATED_MEMOBJECT>()() == nullptr) {
        cl_buffer_region region{origin, span * sizeof(float)};
        return caller.createSubBuffer(0, CL_BUFFER_CREATE_TYPE_REGION, &region);
    }
    cl::Buffer scratch(context_, CL_MEM_READ_WRITE, span * sizeof(float));
    if (is_input)
        in_copies_.push_back({caller, scratch, buffer.offset, 0, planes, count, stride});
    else
        out_copies_.push_back({scratch, caller, 0, buffer.offset, planes, count, stride});
    return scratch;
}

std::vector<cl::Event> PlacedBuffers::enqueue_copies(cl::CommandQueue& queue, const std::vector<PlaneCopies>& copies,
                                                     const std::vector<cl::Event>& wait)
{
    std::vector<cl::Event> done;
    for (const PlaneCopies& copy : copies)
        for (int plane = 0; plane < copy.planes; ++plane) {
            const std::size_t plane_start = static_cast<std::size_t>(plane * copy.stride);
            cl::Event event;
            queue.enqueueCopyBuffer(copy.from, copy.to, (copy.from_offset + plane_start) * sizeof(float),
                                    (copy.to_offset + plane_start) * sizeof(float), copy.count * sizeof(float),
                                    wait.empty() ? nullptr : &wait, &event);
            done.push_back(event);
        }
    return done;
}

std::vector<cl::Event> PlacedBuffers::before_kernel(cl::CommandQueue& queue, const std::vector<cl::Event>& wait)
{
    if (in_copies_.empty())
        return wait;
    std::vector<cl::Event> ready = wait;
    for (const cl::Event& event : enqueue_copies(queue, in_copies_, wait))
        ready.push_back(event);
    return ready;
}

cl::Event PlacedBuffers::after_kernel(cl::CommandQueue& queue, const cl::Event& kernel)
{
    if (out_copies_.empty())
        return kernel;
    std::vector<cl::Event> copies = enqueue_copies(queue, out_copies_, {kernel});
    cl::Event all;
    queue.enqueueMarkerWithWaitList(&copies, &all);
    return all;
}

std::vector<cl::Event> wait_list(cl_uint count, const cl_event* events)
{
    if (count > 0 && !events)
        throw InvalidArgument("wait", "NULL with wait_count " + std::to_string(count), "an array of wait_count events");
    std::vector<cl::Event> list;
    for (cl_uint i = 0; i < count; ++i) {
        if (!events[i])
            throw InvalidArgument("wait", "a NULL event at index " + std::to_string(i), "valid events");
        list.emplace_back(events[i], true);
    }
    return list;
}

void hand_over(const cl::Event& event, cl_event* out)
{
    if (!out)
        return;
    if (event() != nullptr)
        clRetainEvent(event());
    *out = event();
}

} // namespace ggxcl::capi
