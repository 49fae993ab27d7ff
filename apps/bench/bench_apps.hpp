// bench_apps.hpp - `ggx` timed as whole processes.  Start-up: process start
// to first result (`ggx sample -n 1`, one caps sample written), once with an
// empty PoCL kernel cache (cold: the program is built) and then repeatedly
// with that cache warm.  The commands as a user runs them (start,
// build from a warm cache, sampling, conversion, file): `ggx sample` of caps
// m and pdf_m into an .npy file in RAM (/dev/shm where there is one) and
// `ggx histogram --no-png`, each the median of 5 runs in ns per sample, set
// beside the write job of the same fields; .csv and .ply once each, for
// what those formats cost.  Beside them, what bounds them from below: the
// .npy's bytes written from memory into a file in the same folder, and the
// histogram's device time from its sidecar.
#pragma once

#include <string>

#include "bench_report.hpp"

namespace ggxapp {

// `device`: the options that choose the device (ApiChoice::arguments).
StartupTiming measure_startup(const DeviceArguments& device, int warm_runs);
AppTimings measure_apps(const DeviceArguments& device, std::uint32_t count);

} // namespace ggxapp
