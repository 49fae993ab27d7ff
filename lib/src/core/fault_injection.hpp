// fault_injection.hpp - the faults that GGXCL_INJECT_FAULT asks for, so
// that tests provoke device memory exhaustion and a lost device on any
// device (docs/RELIABILITY.md):
//   alloc-above=BYTES   every device buffer larger than BYTES fails to
//                       allocate (CL_MEM_OBJECT_ALLOCATION_FAILURE)
//   lost-after=N        the first N kernel launches of the process run, every
//                       later one fails as on a lost device (CL_DEVICE_NOT_AVAILABLE)
// device_faults.cpp applies them; nothing else reads the variable.
#pragma once

#include <cstdint>

namespace ggxcl::detail {

struct InjectedFault {
    std::uint64_t alloc_above = 0;  // 0: no allocation fault
    std::uint64_t lost_after = 0;
    bool lost = false;              // lost_after is set
};

// The fault the environment asks for now, and in `launches_before` the
// launches counted since it was set (count_launch counts this call as one).
// The value is parsed when it changes; a malformed one is refused
// (InvalidArgument naming the forms allowed) on every call.  While the
// variable has never been set, a call costs one getenv and no lock.
// Hidden: not exported by libggxcl (the variable is the interface).
__attribute__((visibility("hidden"))) InjectedFault injected_fault(bool count_launch,
                                                                   std::uint64_t& launches_before);

} // namespace ggxcl::detail
