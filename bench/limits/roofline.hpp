// roofline.hpp - how close a kernel runs to its device's own limits, as
// arithmetic on given numbers (docs/COST-PROBES.md, "How close to the limit"):
//   compute limit, ns per sample = max over classes c of count_c / peak_c
//     (the classes run on separate units side by side, as on a GPU);
//   its sum form = sum over c of count_c / peak_c
//     (one set of units for all classes, as on a CPU), reported beside it;
//   bandwidth limit = bytes per sample / the store-only kernel's bytes per ns;
//   % of the limit = the tighter (larger) limit / the measured time x 100.
#pragma once

#include <cstddef>

#include "bench_peak.hpp"
#include "bench_speed.hpp"
#include "op_counts.hpp"

namespace ggxapp {

struct ComputeLimit {
    double ns = 0;      // max form
    OpClass binding = OpClass::float_op;  // the class that gives the max
    double sum_ns = 0;  // sum form
};

// Throws std::invalid_argument naming the class when a counted class has no positive peak.
ComputeLimit compute_limit(const OpCounts& per_sample, const PeakRates& peaks);

// Bytes a job stores per sample (write: m's three planes and pdf_m; write-o: o's and pdf_o; furnace:
// a conductor's two partial sums per GGX_FURNACE_PER_ITEM samples; store: what store_only stores per work-item).  Throws
// std::invalid_argument for the jobs that also read per sample (world, per-sample).
double stored_bytes_per_sample(BenchJob job);

// ns per sample at the store-only kernel's bandwidth.
double bandwidth_limit_ns(double bytes_per_sample, double store_ns_per_sample);

// limit / measured x 100; throws std::invalid_argument when measured_ns is not positive.
double percent_of_limit(double limit_ns, double measured_ns);

} // namespace ggxapp
