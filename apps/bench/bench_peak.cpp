// bench_peak.cpp - the compute peak probe: one kernel per op class, sized
// to a few ms per run, median of 5 runs.
#include "bench_peak.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "child_process.hpp"

namespace ggxapp {

namespace {

constexpr int chains = 8, steps = 32;  // per work-item: steps x chains dependent-in-chain operations
constexpr double target_ns = 4e6;      // one timed run
constexpr std::size_t min_items = 1u << 12, max_items = 1u << 24;
constexpr int runs = 5;

// One macro per class: a step of one chain, which reads the chain's value once (a step that read it
// twice, x = x * x, makes an expression whose paths double with every step: NVIDIA's compiler took
// minutes on it).  The int step is two ops (xor, add: alternating, so that no compiler folds the
// chain); the multiply's xor keeps compilers from folding the chain of multiplies into a power of a,
// and is not counted (it issues beside the multiply on GPUs; on a CPU the rate is a lower bound).
const char* const source_text = R"CL(
#define R2(S) S S
#define STEPS(S) R2(R2(R2(R2(R2(S)))))
#define EACH_CHAIN(OP) OP(x0) OP(x1) OP(x2) OP(x3) OP(x4) OP(x5) OP(x6) OP(x7)
#define PEAK_KERNEL(name, T, OP)                                                        \
    __kernel void name(__global T* restrict out, T a, T b)                              \
    {                                                                                   \
        uint j = (uint)get_global_id(0);                                                \
        T x0 = a + (T)(j & 255u) * b, x1 = x0 + b, x2 = x1 + b, x3 = x2 + b;            \
        T x4 = x3 + b, x5 = x4 + b, x6 = x5 + b, x7 = x6 + b;                           \
        STEPS(EACH_CHAIN(OP))                                                           \
        out[j] = ((x0 + x1) + (x2 + x3)) + ((x4 + x5) + (x6 + x7));                      \
    }
#define FMA_STEP(x) x = x * a + b;
#define INT_STEP(x) x = (x ^ a) + b;
#define MUL_STEP(x) x = (x * a) ^ b;
#define MUL64_STEP(x) x = (uint)(((ulong)x * 0xD256D193ul) >> 32);
#define SQRT_STEP(x) x = sqrt(x);
#define DIV_STEP(x) x = a / x;
PEAK_KERNEL(peak_float, float, FMA_STEP)
PEAK_KERNEL(peak_int, uint, INT_STEP)
PEAK_KERNEL(peak_int_mul, uint, MUL_STEP)
PEAK_KERNEL(peak_int_mul64, uint, MUL64_STEP)
PEAK_KERNEL(peak_sqrt, float, SQRT_STEP)
PEAK_KERNEL(peak_division, float, DIV_STEP)
)CL";

bool is_float_class(OpClass c)
{
    return c == OpClass::float_op || c == OpClass::sqrt || c == OpClass::division;
}

// Nanoseconds of one run of `items` work-items in groups of `group` (fixed: a driver that picks the
// group size by the count JIT-compiles again for each new size), by the event's profile, or by wall
// clock where the profile cannot be right (missing, or below 1% or far above the wall-clock time:
// Mesa 22.3 rusticl reports 1 ns), as time_interleaved decides (bench_speed.cpp).
double run_ns(cl::CommandQueue& queue, cl::Kernel& kernel, std::size_t items, std::size_t group)
{
    cl::Event done;
    auto start = std::chrono::steady_clock::now();
    queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(items), cl::NDRange(group), nullptr, &done);
    done.wait();
    const double wall = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    cl_ulong begin = 0, end = 0;
    if (done.getProfilingInfo(CL_PROFILING_COMMAND_START, &begin) != CL_SUCCESS ||
        done.getProfilingInfo(CL_PROFILING_COMMAND_END, &end) != CL_SUCCESS || end <= begin)
        return wall;
    const double profiled = double(end - begin);
    return profiled >= 0.01 * wall && profiled <= 1.5 * wall + 1e6 ? profiled : wall;
}

// Operations per second of one class: a warm-up run (JIT) sizes the timed runs.
double measure_class(ggxcl::Sampler& sampler, cl::Program& program, cl::Buffer& out, OpClass c)
{
    cl::Kernel kernel(program, peak_kernel_name(c));
    kernel.setArg(0, out);
    if (is_float_class(c)) {
        kernel.setArg(1, cl_float(0.999f));
        kernel.setArg(2, cl_float(1e-3f));
    } else {
        kernel.setArg(1, cl_uint(0x9E3779B9u));
        kernel.setArg(2, cl_uint(12345u));
    }
    cl::CommandQueue& queue = sampler.queue();
    const std::size_t group = sampler.work_group_size();
    std::size_t items = 1u << 16;
    run_ns(queue, kernel, items, group);  // JIT
    const double first = run_ns(queue, kernel, items, group);
    const double scaled = double(items) * target_ns / std::max(first, 1.0);
    items = std::clamp<std::size_t>(std::size_t(scaled), min_items, max_items) / group * group;
    std::vector<double> ns;
    for (int r = 0; r < runs; ++r)
        ns.push_back(run_ns(queue, kernel, items, group));
    std::sort(ns.begin(), ns.end());
    return double(items) * peak_ops_per_item(c) / (ns[ns.size() / 2] * 1e-9);
}

} // namespace

const std::string& peak_probe_source()
{
    static const std::string source = source_text;
    return source;
}

const char* peak_kernel_name(OpClass c)
{
    switch (c) {
    case OpClass::float_op: return "peak_float";
    case OpClass::int_op: return "peak_int";
    case OpClass::int_mul: return "peak_int_mul";
    case OpClass::int_mul_wide: return "peak_int_mul64";
    case OpClass::sqrt: return "peak_sqrt";
    case OpClass::division: return "peak_division";
    }
    return "?";
}

double peak_ops_per_item(OpClass c)
{
    return double(chains) * steps * (c == OpClass::int_op ? 2 : 1);
}

PeakRates measure_peaks(ggxcl::Sampler& sampler)
{
    auto start = std::chrono::steady_clock::now();
    const cl::Device& device = sampler.device();
    cl::Program program(sampler.context(), peak_probe_source());
    const std::string options = ggxcl::device_options(device) + ggxcl::precision_options(device, ggxcl::Precision::precise);
    try {
        program.build({device}, options.c_str());
    } catch (const cl::Error&) {
        throw std::runtime_error("the peak probe does not build (" + options + "): " +
                                 program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device));
    }
    cl::Buffer out(sampler.context(), CL_MEM_WRITE_ONLY, max_items * sizeof(float));
    PeakRates peaks;
    for (OpClass c : all_op_classes)
        peaks.ops_per_s[static_cast<std::size_t>(c)] = measure_class(sampler, program, out, c);
    peaks.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return peaks;
}

std::string peak_rates_text(const PeakRates& peaks)
{
    std::ostringstream text;
    text << std::setprecision(17);
    for (OpClass c : all_op_classes)
        text << peak_kernel_name(c) << " " << peaks[c] << "\n";
    text << "seconds " << peaks.seconds << "\n";
    return text.str();
}

PeakRates parse_peak_rates(const std::string& text)
{
    std::istringstream lines(text);
    PeakRates peaks;
    for (OpClass c : all_op_classes) {
        std::string name;
        double rate = 0;
        if (!(lines >> name >> rate) || name != peak_kernel_name(c) || !(rate > 0))
            throw std::runtime_error("the peak probe printed no rate for " + std::string(peak_kernel_name(c)) + ": " +
                                     text.substr(0, 400));
        peaks.ops_per_s[static_cast<std::size_t>(c)] = rate;
    }
    std::string word;
    if (!(lines >> word >> peaks.seconds) || word != "seconds")
        throw std::runtime_error("the peak probe printed no time: " + text.substr(0, 400));
    return peaks;
}

PeakRates measure_peaks_in_child(const std::string& device, double limit_s)
{
    std::vector<std::string> arguments = {"peak-probe"};
    if (!device.empty())
        arguments.insert(arguments.end(), {"--device", device});
    const ChildOutput child = run_child("/proc/self/exe", arguments, limit_s);
    if (!exited_ok(child.status))
        throw std::runtime_error("`ggx peak-probe` " + describe_exit(child.status) + ": " + child.err.substr(0, 2000));
    return parse_peak_rates(child.out);
}

} // namespace ggxapp
