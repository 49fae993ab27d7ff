// queue_waits.hpp - copies between host and device that return when done,
// and waiting for a queue to empty, each by waiting on an event of its own.
// Mesa rusticl 22.3 returns from clFinish, and from a blocking read or
// write, at once when a clFlush (from any thread) has already taken the
// queue's pending commands: measured, a read still queued after clFinish,
// and on a Sampler's queue shared by threads, blocking reads that returned
// before their bytes arrived.  Waiting on the command's own event is exact
// everywhere.
#pragma once

#include <cstddef>

#include "ggxcl/opencl.hpp"

namespace ggxcl::detail {

inline void read_and_wait(cl::CommandQueue& queue, const cl::Buffer& buffer, std::size_t offset, std::size_t bytes,
                          void* host)
{
    cl::Event done;
    queue.enqueueReadBuffer(buffer, CL_FALSE, offset, bytes, host, nullptr, &done);
    done.wait();
}

inline void write_and_wait(cl::CommandQueue& queue, const cl::Buffer& buffer, std::size_t offset, std::size_t bytes,
                           const void* host)
{
    cl::Event done;
    queue.enqueueWriteBuffer(buffer, CL_FALSE, offset, bytes, host, nullptr, &done);
    done.wait();
}

// Returns when every command enqueued on `queue` before it has completed.
inline void drain(cl::CommandQueue& queue)
{
    cl::Event all_done;
    queue.enqueueMarkerWithWaitList(nullptr, &all_done);
    all_done.wait();
}

} // namespace ggxcl::detail
