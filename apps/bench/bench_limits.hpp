// bench_limits.hpp - the report's "How close to this device's limits": each
// write and fused (furnace) row against its compute limit (its op counts
// over the peaks measured in the same run) and its bandwidth limit (the
// store-only row), as CSV columns and Markdown tables (bench/check_targets.py
// holds the project's target on them).  Arithmetic in roofline.hpp.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bench_report.hpp"
#include "roofline.hpp"

namespace ggxapp {

struct RowLimit {
    std::optional<ComputeLimit> compute;  // none without op counts or peaks
    std::optional<double> bandwidth_ns;   // none without the store-only row
    double tighter_ns = 0;                // the larger of the two
    bool compute_binds = false;
    double percent = 0;                   // tighter / measured x 100
};

// The limits of a conductor's write or furnace row (nothing for other jobs, dielectric rows, or when
// neither limit is known).
std::optional<RowLimit> row_limit(const BenchRow& row, const BenchReport& report);

// The CSV's limit columns: the header's part (starting with a comma) and a row's cells.
std::string limit_csv_header();
std::string limit_csv_cells(const BenchRow& row, const BenchReport& report);

// The section's Markdown: the peaks, the limits table of precise write and furnace rows, and the
// op counts per sample.
void write_limit_section(std::ostream& md, const BenchReport& report);

} // namespace ggxapp
