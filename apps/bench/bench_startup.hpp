// bench_startup.hpp - start-up time of the `ggx` tool: process start to
// first result (`ggx sample -n 1`, one caps sample written), once with an
// empty PoCL kernel cache (cold: the program is built) and then repeatedly
// with that cache warm.
#pragma once

#include "bench_report.hpp"

namespace ggxapp {

// `device`: the options that choose the device (ApiChoice::arguments).
StartupTiming measure_startup(const DeviceArguments& device, int warm_runs);

} // namespace ggxapp
