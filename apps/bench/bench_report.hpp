// bench_report.hpp - what `ggx bench` measured and how it is written: the
// rows (one per device x method x precision mode x job, each with its api;
// the native baseline with precision and api "native"; with --eta a rough
// dielectric's rows, eta set, beside conductor rows of the same jobs),
// derived columns (efficiency, RMSE at equal time), the CSV, the Markdown
// report (a section per device, which sampler to pick first, and with two
// devices their rows side by side), and the charts.
#pragma once

#include <string>
#include <vector>

#include "bench_accuracy.hpp"
#include "bench_speed.hpp"

namespace ggxapp {

struct BenchRow {
    std::string api;  // the device's API label ("opencl", "vulkan (glsl)"); "native" for the C++ baseline
    std::string method, precision, job;
    std::string sequence = "philox";  // where the uniforms came from (precise rows also with sobol)
    Timing timing;                // ns per sample
    bool has_error = false;       // numerical error measured
    NumericalError error;
    double variance = 0;          // albedo estimator variance per sample (0: not measured)
    double mean_albedo = 0;       // mean over the table's cells of the albedo estimate
    double rmse_measured = 0;     // precise furnace rows: the table's RMSE at the budget, measured (0: not)
    double pdf_disagreement = -1; // a user sampler's write rows: the fraction of pdf_o whose pdf from (i, o)
                                  // differs by more than 1e-3 (-1: not measured)
    float eta = 0;                // a rough dielectric's relative index (SampleParams::eta); 0: a conductor
    std::string transport;        // dielectric rows: radiance or importance
    DielectricAccuracy dielectric;  // dielectric furnace rows: reflectance and transmittance against the reference
};

// The options that choose a child `ggx`'s device (ApiChoice::arguments).
using DeviceArguments = std::vector<std::string>;

struct StartupTiming {
    bool measured = false;
    double cold_ms = 0;           // fresh kernel cache
    Timing warm_ms;               // cache warm, median of runs
};

struct EnqueueTiming {
    bool measured = false;
    std::uint32_t count = 4096;   // samples per enqueue
    int calls = 1000;
    Timing host_us;               // microseconds per call, warm caches
    double second_sampler_first_us = 0;  // first call of another Sampler on the same context
    // Enqueue and finish, microseconds, alternated side by side: every buffer at offset 0, and every
    // buffer at an odd offset (the kernels take offsets: no sub-buffer, no copy).
    std::uint64_t odd_offset = 37;
    Timing at_zero_us, at_odd_offset_us;
};

struct AppTimings {
    bool measured = false;
    std::uint32_t count = 0, text_count = 0;  // samples per run (text formats: text_count)
    std::string folder;                       // where the files went
    Timing sample_npy, histogram;             // ns per sample, whole process, median of 5
    Timing npy_file_floor;                    // ns per sample: the .npy's bytes written from memory
    double histogram_device = 0;              // ns per sample: the last histogram run's binning alone
    double sample_csv = 0, sample_ply = 0;    // ns per sample, one run each
};

// A device of the run: its rows' api, its name as reports give it, how its rows were timed.
struct BenchDeviceNote {
    std::string api, label, clock;
};

struct BenchReport {
    std::string command, date, machine;
    std::vector<BenchDeviceNote> devices;  // in the report's order
    std::uint32_t count = 0, native_count = 0;
    int repeats = 0, threads = 0, scene_size = 0;
    std::uint64_t samples_per_cell = 0;
    double budget_ms = 1.0;       // time budget of the whole albedo table for the RMSE column
    int rmse_streams = 8;         // independent streams per cell of the measured RMSE
    double alpha = 0, theta = 0;  // the speed runs' configuration
    float eta = 0;                // --eta: the dielectric rows' index (0: none)
    std::string transport = "radiance";  // --transport: theirs
    std::vector<BenchRow> rows;
    bool has_vectorized = false;
    Timing vectorized;            // native fused caps, its loop vectorized by the compiler
    std::string native_unavailable;  // why the native baseline is missing (empty: measured or --no-native)
    StartupTiming startup;
    EnqueueTiming enqueue;
    AppTimings apps;
};

// A row of (method, precision, job) with its timing, nothing else measured.
BenchRow row_of(const std::string& method, const std::string& precision, const std::string& job, Timing timing);
// The first row of (method, precision, job, sequence): a conductor's (eta 0) or, with dielectric, the
// dielectric's (eta set); null when there is none.
const BenchRow* find_row(const BenchReport& r, const std::string& method, const std::string& precision,
                         const std::string& job, const std::string& sequence = "philox", bool dielectric = false);

// 1 / (variance x seconds per sample), and the RMSE of each cell of the table
// after the budget is spent on it: sqrt(variance / (budget / (cells x time))),
// the Monte Carlo model, true for independent uniforms only (rmse_measured
// holds the measured one, which Sobol points need).
// The samples per cell the budget buys at the row's speed.
std::uint64_t samples_at_budget(const BenchRow& row, const BenchReport& report);
double efficiency(const BenchRow& row);
double rmse_at_budget(const BenchRow& row, const BenchReport& report);

// The rows as CSV; with_process_rows adds start-up, the commands and enqueues (see bench_csv's
// process_rows), what bench/check_targets.py reads beside the device rows.
std::string bench_csv(const BenchReport& report, bool with_process_rows = true);

// The report of one device: its rows and the native ones.
BenchReport device_report(const BenchReport& report, const std::string& api);

// The two charts of a device (paths relative to the report; empty: none).
struct ChartFiles {
    std::string speed_error, speed_rmse;
};
// The report; `charts`: one pair per device of report.devices, or none.
std::string bench_markdown(const BenchReport& report, const std::vector<ChartFiles>& charts);

// The machine: CPU model and logical cores (Linux /proc/cpuinfo).
std::string machine_description();

} // namespace ggxapp
