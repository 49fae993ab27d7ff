// c_events.hpp - the events of the C API's enqueue calls: the caller's
// wait list, and the event handed back.  (The caller's buffers and offsets
// go to the kernels as they are: c_sampler.cpp.)
#pragma once

#include <vector>

#include "ggxcl/ggxcl.h"
#include "ggxcl/opencl.hpp"

namespace ggxcl::capi {

// The caller's wait list as events (retained), and an event handed to the caller (retained for it).
std::vector<cl::Event> wait_list(cl_uint count, const cl_event* events);
void hand_over(const cl::Event& event, cl_event* out);

} // namespace ggxcl::capi
