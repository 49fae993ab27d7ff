// bench_peak.hpp - the device's own compute peaks, measured in ggx-limits'
// run the way clpeak measures them: per op class, a kernel of 8 independent
// chains per work-item, each a long unrolled line of dependent operations
// (no loop, so that PoCL still vectorizes across work-items), enough
// work-items for a run of about 40 ms, the fastest of 5 event-profiled runs, and
// a sum of the chains written per work-item so nothing is optimized away.
// One op: one fma (a*b+c, contracted), one add or xor, one 32-bit multiply,
// one 32 x 32 -> 64-bit product with its high half taken (as Philox does),
// one sqrt, one float division.  Built with the precise mode's options and
// the device's own (precision_options, device_options).
#pragma once

#include <array>
#include <string>

#include <ggxcl/ggxcl.hpp>

#include "op_counts.hpp"

namespace ggxapp {

// Operations per second of the whole device, per class, counted per work-item (a work-item's scalar op,
// however the device spreads work-items over SIMD lanes).
struct PeakRates {
    std::array<double, op_class_count> ops_per_s{};
    double operator[](OpClass c) const { return ops_per_s[static_cast<std::size_t>(c)]; }
    double seconds = 0;  // wall time the probe took, build included
};

// The probe kernels' source, and the operations per work-item of class `c`'s kernel (its chains'
// steps; the start values and the final sum are not counted).
const std::string& peak_probe_source();
const char* peak_kernel_name(OpClass c);
double peak_ops_per_item(OpClass c);

// Measures every class on the sampler's device and queue (which profiles).  Throws ggxcl or cl errors.
PeakRates measure_peaks(ggxcl::Sampler& sampler);

// The same in a child process, `ggx-limits --peak-probe` on the device `device` selects (a build inside a
// driver cannot be interrupted, and one compiler took minutes on an earlier probe): stopped after
// `limit_s` seconds.  Throws std::runtime_error saying why when the child fails, prints something
// else than its rates, or runs past the limit (ChildTimedOut).
PeakRates measure_peaks_in_child(const std::string& device, double limit_s);

// The child's report: a line "<kernel name> <ops per s>" per class, then "seconds <s>"; and back.
std::string peak_rates_text(const PeakRates& peaks);
PeakRates parse_peak_rates(const std::string& text);

} // namespace ggxapp
