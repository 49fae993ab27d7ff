// bench_limits.hpp - ggx-limits' report, "How close to this device's limits":
// each write and fused (furnace) row against its compute limit (its op counts
// over the peaks measured in the same run) and its bandwidth limit (the
// store-only row), as CSV and Markdown tables (bench/check_targets.py holds
// the project's target on the CSV).  Arithmetic in roofline.hpp.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bench_report.hpp"
#include "roofline.hpp"

namespace ggxapp {

// A timed row (method, precision, job, ns per sample: the bench's BenchRow) and its kernel's op counts.
struct LimitRow {
    BenchRow row;
    std::optional<OpCounts> ops;  // none where not counted
};

// What the report reads: the precise write and furnace rows of each method, the store-only row, and
// the device's peaks measured in the same run; why peaks or op counts are missing.
struct LimitReport {
    std::string device;
    std::vector<LimitRow> rows;
    bool has_peaks = false;
    PeakRates peaks;
    std::string peaks_unavailable, ops_unavailable;
};

struct RowLimit {
    std::optional<ComputeLimit> compute;  // none without op counts or peaks
    std::optional<double> bandwidth_ns;   // none without the store-only row
    double tighter_ns = 0;                // the larger of the two
    bool compute_binds = false;
    double percent = 0;                   // tighter / measured x 100
};

// The limits of a write or furnace row (ggx-limits times conductors only; nothing for other jobs, or
// when neither limit is known).
std::optional<RowLimit> row_limit(const LimitRow& row, const LimitReport& report);

// The CSV: a row per timed row, its ns, op counts and limits (percent_of_limit: what
// bench/check_targets.py reads).
std::string limits_csv(const LimitReport& report);

// The Markdown: the peaks, the limits table of precise write and furnace rows, and the op counts per
// sample.
void write_limit_section(std::ostream& md, const LimitReport& report);

} // namespace ggxapp
