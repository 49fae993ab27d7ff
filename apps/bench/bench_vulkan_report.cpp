// bench_vulkan_report.cpp - the report of `ggx bench --api vulkan`
// (bench_vulkan.hpp): the Markdown with its accuracy section, and the CSV.
#include "bench_vulkan.hpp"

#include <sstream>

#include "report_text.hpp"

namespace ggxapp {

namespace {

bool has_user_rows(const ApiBenchReport& r)
{
    for (const ApiBenchRow& row : r.rows)
        if (row.user)
            return true;
    return false;
}

// The accuracy section: a line per sampler and sequence of its precise conductor write and
// furnace rows.
std::string accuracy_markdown(const ApiBenchReport& r)
{
    std::ostringstream md;
    md << "\n## Accuracy on the Vulkan device\n\n"
       << "Precise mode, conductors, measured on " << r.vulkan_device << " as `ggx bench` measures it on OpenCL. "
       << "Error: the samples against the double-precision reference on the same uniforms (a user sampler's only "
          "with --reproduces), angle of m and o and relative pdf, 99th percentile. pdf off: the fraction of a user "
          "sampler's pdf_o that its own pdf function, from (i, o), puts more than 1e-3 away. Variance: the albedo "
          "estimator's per sample over a "
       << r.scene_size << " x " << r.scene_size << " table (" << r.samples_per_cell
       << " samples per cell, philox). RMSE at equal time: the table's on the row's sequence (Sobol points "
          "independently scrambled per stream), measured over " << r.rmse_streams
       << " streams, with " << readable_number(r.budget_ms)
       << " ms of furnace time for the whole table at the Vulkan row's speed: lower is better.\n\n"
       << "| sampler | sequence | angle error p99 (rad) | pdf error p99 | pdf off | variance | furnace ns/sample | "
          "samples per cell | RMSE at equal time |\n"
       << "|---|---|---|---|---|---|---|---|---|\n";
    const auto cell = [](bool has, double value) { return has ? readable_number(value) : std::string("–"); };
    for (const ApiBenchRow& furnace : r.rows) {
        if (furnace.job != "furnace" || furnace.eta != 0.0f || furnace.precision != "precise")
            continue;
        const ApiBenchRow* write = nullptr;
        for (const ApiBenchRow& row : r.rows)
            if (row.job == "write" && row.method == furnace.method && row.sequence == furnace.sequence &&
                row.precision == "precise")
                write = &row;
        const bool error = write && write->has_error, pdf = write && write->pdf_disagreement >= 0;
        md << "| " << furnace.method << " | " << furnace.sequence << " | "
           << cell(error, error ? write->error.angle_p99 : 0) << " | " << cell(error, error ? write->error.pdf_p99 : 0)
           << " | "
           << cell(pdf, pdf ? write->pdf_disagreement : 0) << " | " << cell(furnace.variance > 0, furnace.variance)
           << " | " << readable_number(furnace.vulkan.median) << " | " << furnace.samples_per_cell << " | "
           << cell(furnace.rmse_measured > 0, furnace.rmse_measured) << " |\n";
    }
    return md.str();
}

} // namespace

std::string api_bench_markdown(const ApiBenchReport& r)
{
    std::ostringstream md;
    md << "# Vulkan against OpenCL\n\n"
       << "- Vulkan device: " << r.vulkan_device << ", shaders in " << r.language << "\n"
       << "- OpenCL device: " << (r.opencl_device.empty() ? "none (" + r.opencl_unavailable + ")" : r.opencl_device)
       << "\n- Machine: " << r.machine << "; " << r.date << "\n"
       << "- Command: `" << r.command << "`\n"
       << "- " << r.count << " samples per run, alpha " << r.alpha << ", view " << r.theta
       << " degrees from the normal; the median of " << r.repeats
       << " wall-clock runs of the whole library call (fastest–slowest), both APIs timed back to back in "
          "each round.  write: m and pdf_m into host memory; furnace: the fused white-furnace estimator.\n"
       << "- Vulkan / OpenCL below 1: Vulkan is faster."
       << (has_user_rows(r) ? "  User samplers in GLSL or HLSL run on Vulkan alone." : "") << "\n\n"
       << "| method | precision | job | sequence | Vulkan ns/sample | OpenCL ns/sample | Vulkan / OpenCL |\n"
       << "|---|---|---|---|---|---|---|\n";
    const auto timing = [](const Timing& t) {
        return t.median > 0 ? readable_number(t.median) + " (" + readable_number(t.low) + "–" + readable_number(t.high) + ")"
                            : std::string("–");
    };
    for (const ApiBenchRow& row : r.rows)
        md << "| " << row.method << " | " << row.precision << " | " << row.job
           << (row.eta != 0.0f ? " (dielectric, eta " + readable_number(row.eta) + ")" : "") << " | " << row.sequence
           << " | " << timing(row.vulkan) << " | " << timing(row.opencl) << " | "
           << (row.ratio() > 0 ? readable_number(row.ratio()) : "–") << " |\n";
    if (r.accuracy)
        md << accuracy_markdown(r);
    return md.str();
}

std::string api_bench_csv(const ApiBenchReport& r)
{
    std::ostringstream csv;
    csv << "method,precision,job,sequence,eta,vulkan_ns,vulkan_low,vulkan_high,opencl_ns,opencl_low,opencl_high,"
           "ratio,vulkan_device,opencl_device,user,angle_p99,pdf_p99,pdf_disagreement,variance,samples_per_cell,"
           "rmse_measured\n";
    for (const ApiBenchRow& row : r.rows)
        csv << row.method << "," << row.precision << "," << row.job << "," << row.sequence << "," << row.eta << ","
            << row.vulkan.median << "," << row.vulkan.low << "," << row.vulkan.high << "," << row.opencl.median << ","
            << row.opencl.low << "," << row.opencl.high << "," << row.ratio() << ",\"" << r.vulkan_device << "\",\""
            << r.opencl_device << "\"," << (row.user ? 1 : 0) << ","
            << (row.has_error ? row.error.angle_p99 : -1.0) << "," << (row.has_error ? row.error.pdf_p99 : -1.0) << ","
            << row.pdf_disagreement << "," << row.variance << "," << row.samples_per_cell << "," << row.rmse_measured
            << "\n";
    return csv.str();
}

} // namespace ggxapp
