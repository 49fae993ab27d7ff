// cmd_bench.cpp - `ggx bench`: device speed of every method in every
// precision mode, writing m and pdf_m into device buffers (the issue-4
// target configuration): event-profiled nanoseconds per sample, the median
// of --repeats timed runs after a warm-up (which builds and JIT-compiles the
// variant), with the minimum and maximum.  Prints a Markdown table; --csv
// writes the same rows.
#include <algorithm>
#include <iostream>
#include <sstream>

#include "atomic_file.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "sample_options.hpp"

namespace ggxapp {

namespace {

struct BenchCommand {
    SampleOptions options;
    std::string count = "2^24", repeats = "7", csv;
};

struct Timing {
    double median, low, high;
};

Timing time_variant(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params, std::uint32_t count, int repeats,
                    const ggxcl::DeviceOutputs& out)
{
    sampler.enqueue(sampler.queue(), params, {1, 0, count}, out).wait();  // warm-up: build and JIT
    std::vector<double> ns;
    for (int r = 0; r < repeats; ++r) {
        cl::Event done = sampler.enqueue(sampler.queue(), params, {std::uint64_t(r) + 2, 0, count}, out);
        done.wait();
        double elapsed = double(done.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                                done.getProfilingInfo<CL_PROFILING_COMMAND_START>());
        ns.push_back(elapsed / count);
    }
    std::sort(ns.begin(), ns.end());
    return {ns[ns.size() / 2], ns.front(), ns.back()};
}

void run_bench(const BenchCommand& bench)
{
    std::uint64_t count = parse_count("-n", bench.count);
    if (count > (1u << 30))
        throw UsageError("-n", bench.count, "at most 2^30 samples per timed run");
    std::uint64_t repeats = parse_whole("--repeats", bench.repeats, 5, 101);
    if (!bench.csv.empty())
        check_writable_folder("--csv", bench.csv);
    ggxcl::Sampler sampler(bench.options.device);
    ggxcl::DeviceOutputs out;
    out.m = cl::Buffer(sampler.context(), CL_MEM_WRITE_ONLY, 3 * count * sizeof(float));
    out.pdf_m = cl::Buffer(sampler.context(), CL_MEM_WRITE_ONLY, count * sizeof(float));
    std::ostringstream csv;
    csv << "method,precision,ns_per_sample_median,ns_min,ns_max,samples_per_second\n";
    std::cout << "device: " << sampler.device_name() << "; " << count << " samples per run, median of " << repeats
              << " runs, m and pdf_m written\n\n| method | precision | ns/sample (median) | min | max | G samples/s |\n"
              << "|---|---|---|---|---|---|\n";
    for (const char* mode : {"precise", "fast", "relaxed"})
        for (ggxcl::Method method : ggxcl::all_methods) {
            SampleOptions options = bench.options.for_method(method);
            options.precision = mode;
            Timing t = time_variant(sampler, options.params_for(method), std::uint32_t(count), int(repeats), out);
            std::cout << "| " << ggxcl::method_name(method) << " | " << mode << " | " << t.median << " | " << t.low
                      << " | " << t.high << " | " << 1.0 / t.median << " |\n";
            csv << ggxcl::method_name(method) << "," << mode << "," << t.median << "," << t.low << "," << t.high << ","
                << 1e9 / t.median << "\n";
        }
    if (!bench.csv.empty())
        write_text_file(bench.csv, csv.str());
}

} // namespace

Action add_bench_command(CLI::App& app)
{
    auto state = std::make_shared<BenchCommand>();
    CLI::App* cmd = app.add_subcommand("bench", "Time every method in every precision mode on a device");
    state->options.add_view_options(*cmd);
    cmd->add_option("-n,--count", state->count, "samples per timed run")->capture_default_str();
    cmd->add_option("--repeats", state->repeats, "timed runs per variant (median reported)")->capture_default_str();
    cmd->add_option("--csv", state->csv, "also write the rows to this CSV file");
    return [cmd, state] {
        if (*cmd)
            run_bench(*state);
    };
}

} // namespace ggxapp
