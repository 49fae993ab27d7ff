// bench_limits.cpp - ggx-limits' report: per row, the compute and bandwidth
// limits, the CSV and the tables.
#include "bench_limits.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "report_text.hpp"

namespace ggxapp {

namespace {

std::string giga(double per_s)
{
    return fixed(per_s * 1e-9, per_s < 1e10 ? 2 : 1) + " G";
}

const LimitRow* find_limit_row(const LimitReport& r, const std::string& method, const std::string& precision,
                               const std::string& job)
{
    for (const LimitRow& row : r.rows)
        if (row.row.method == method && row.row.precision == precision && row.row.job == job)
            return &row;
    return nullptr;
}

// The precise conductor rows of the limits table, method by method (library order), write then furnace.
std::vector<const LimitRow*> table_rows(const LimitReport& r)
{
    std::vector<const LimitRow*> rows;
    for (ggxcl::Method m : ggxcl::all_methods)
        for (const char* job : {"write", "furnace"})
            if (const LimitRow* row = find_limit_row(r, std::string(ggxcl::method_name(m)), "precise", job))
                rows.push_back(row);
    return rows;
}

std::string compute_cell(const RowLimit& limit)
{
    if (!limit.compute)
        return "–";
    return fixed(limit.compute->ns, 2) + " (" + op_class_name(limit.compute->binding) + ")";
}

void write_peaks(std::ostream& md, const LimitReport& r)
{
    if (!r.ops_unavailable.empty()) {  // the probe is not run: it has nothing to divide
        md << "Compute limits unavailable: no op counts (" << r.ops_unavailable << ").\n\n";
        return;
    }
    if (!r.has_peaks) {
        md << "Compute limits unavailable: the peak probe failed (" << r.peaks_unavailable << ").\n\n";
        return;
    }
    md << "Peaks of this device measured in this run (operations per second over all work-items, one "
          "work-item's scalar op each; fma counted as one op; probe "
       << fixed(r.peaks.seconds, 2) << " s):";
    for (OpClass c : all_op_classes)
        md << (c == OpClass::float_op ? " " : ", ") << op_class_name(c) << " " << giga(r.peaks[c]);
    md << ".\n\n";
}

void write_ops_table(std::ostream& md, const std::vector<const LimitRow*>& rows)
{
    md << "\nOperations per sample by class, static count of the kernel's LLVM IR (clang -O3, the runtime's "
          "source and options; both sides of every branch):\n\n| method | job |";
    for (OpClass c : all_op_classes)
        md << " " << op_class_name(c) << " |";
    md << " other |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const LimitRow* row : rows) {
        if (!row->ops)
            continue;
        md << "| " << row->row.method << " | " << row->row.job << " |";
        for (OpClass c : all_op_classes)
            md << " " << fixed((*row->ops)[c], 1) << " |";
        md << " " << (row->ops->other.empty() ? "–" : row->ops->other_text()) << " |\n";
    }
}

} // namespace

std::optional<RowLimit> row_limit(const LimitRow& limit_row, const LimitReport& report)
{
    const BenchRow& row = limit_row.row;
    if (row.job != "write" && row.job != "furnace")
        return std::nullopt;
    RowLimit limit;
    if (limit_row.ops && report.has_peaks)
        limit.compute = compute_limit(*limit_row.ops, report.peaks);
    if (const LimitRow* store = find_limit_row(report, "all", "store-only", "write"))
        limit.bandwidth_ns = bandwidth_limit_ns(
            stored_bytes_per_sample(row.job == "write" ? BenchJob::write : BenchJob::furnace), store->row.timing.median);
    if (!limit.compute && !limit.bandwidth_ns)
        return std::nullopt;
    const double compute_ns = limit.compute ? limit.compute->ns : 0.0;
    limit.compute_binds = compute_ns >= limit.bandwidth_ns.value_or(0.0);
    limit.tighter_ns = limit.compute_binds ? compute_ns : *limit.bandwidth_ns;
    limit.percent = percent_of_limit(limit.tighter_ns, row.timing.median);
    return limit;
}

std::string limits_csv(const LimitReport& report)
{
    std::ostringstream csv;
    csv << std::setprecision(6) << "method,precision,job,ns_median,ns_low,ns_high";
    for (OpClass c : all_op_classes) {
        std::string name = op_class_name(c);
        std::replace(name.begin(), name.end(), ' ', '_');
        csv << ",ops_" << name;
    }
    csv << ",ops_other,compute_limit_ns,compute_binding,compute_sum_limit_ns,bandwidth_limit_ns,percent_of_limit\n";
    for (const LimitRow& row : report.rows) {
        const Timing& t = row.row.timing;
        csv << row.row.method << "," << row.row.precision << "," << row.row.job << "," << t.median << "," << t.low
            << "," << t.high;
        for (OpClass c : all_op_classes) {
            csv << ",";
            if (row.ops)
                csv << (*row.ops)[c];
        }
        csv << "," << (row.ops && !row.ops->other.empty() ? std::to_string(row.ops->other.size()) + " kinds" : "");
        const std::optional<RowLimit> limit = row_limit(row, report);
        if (!limit) {
            csv << ",,,,,\n";
            continue;
        }
        if (limit->compute)
            csv << "," << limit->compute->ns << "," << op_class_name(limit->compute->binding) << ","
                << limit->compute->sum_ns;
        else
            csv << ",,,";
        csv << ",";
        if (limit->bandwidth_ns)
            csv << *limit->bandwidth_ns;
        csv << "," << limit->percent << "\n";
    }
    return csv.str();
}

void write_limit_section(std::ostream& md, const LimitReport& r)
{
    const std::vector<const LimitRow*> rows = table_rows(r);
    if (std::none_of(rows.begin(), rows.end(), [&](const LimitRow* row) { return row_limit(*row, r).has_value(); })) {
        md << "\n## How close to this device's limits\n\nNot known here: the limits need the kernels' op counts "
              "(OpenCL C through clang" << (r.ops_unavailable.empty() ? "" : ": " + r.ops_unavailable)
           << ") or the store-only kernel's speed (OpenCL), and neither was measured for this device.\n";
        return;
    }
    md << "\n## How close to this device's limits\n\n" << "Device: " << r.device << ".\n\nEach method's precise write and fused (furnace) jobs against "
          "the limits of this device measured in this run: the compute limit, ns per sample = max over op classes "
          "of (ops per sample / the class's peak), the class that binds in brackets, and beside it the sum over "
          "the classes (the bound where all classes share one set of units, as on a CPU); the bandwidth limit, the "
          "job's stored bytes per sample at the store-only kernel's speed; % = the tighter (larger) limit / the "
          "measured time.\n\n";
    write_peaks(md, r);
    md << "| method | job | measured ns | compute limit ns (binds) | sum over classes ns | bandwidth limit ns | "
          "% of the tighter limit |\n|---|---|---|---|---|---|---|\n";
    for (const LimitRow* row : rows) {
        std::optional<RowLimit> limit = row_limit(*row, r);
        if (!limit)
            continue;
        md << "| " << row->row.method << " | " << row->row.job << " | " << fixed(row->row.timing.median, 2) << " | "
           << compute_cell(*limit) << " | " << (limit->compute ? fixed(limit->compute->sum_ns, 2) : "–") << " | "
           << (limit->bandwidth_ns ? fixed(*limit->bandwidth_ns, 2) : "–") << " | " << fixed(limit->percent, 0)
           << "% (" << (limit->compute_binds ? "compute" : "bandwidth") << ") |\n";
    }
    write_ops_table(md, rows);
}

} // namespace ggxapp
