// c_events.cpp - the events of the C API's enqueue calls (c_events.hpp).
#include "c_api/c_events.hpp"

#include <string>

#include "ggxcl/error.hpp"

namespace ggxcl::capi {

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
