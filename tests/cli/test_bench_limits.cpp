// test_bench_limits.cpp - ggx-limits (bench/limits): the LLVM IR op counter on
// hand-written IR (exact counts; unknown calls named and failing the strict
// count), the roofline arithmetic on given numbers, every bench kernel's IR
// free of unknown operations, the peak probe's kernels counted as the probe
// assumes (nothing folded away) and measured on the device, and the tool's
// report and CSV with a compiler and without one.  The cases that compile
// kernels to IR need clang 15 (clang-15 on PATH, or GGXCL_CLANG): skipped
// without it (skip.hpp).
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <iterator>
#include <regex>
#include <stdexcept>

#include <ggxcl/benchmark.hpp>
#include <ggxcl/cl/ggx_contract.h>

#include "bench_limits.hpp"
#include "bench_peak.hpp"
#include "child_process.hpp"
#include "cli_runner.hpp"
#include "kernel_ir.hpp"
#include "op_counts.hpp"
#include "roofline.hpp"
#include "skip.hpp"

using namespace ggxapp;
using ggxtest::read_all;
namespace fs = std::filesystem;

namespace {

const char* const hand_written_ll = R"LL(
; ModuleID = 'probe.cl'
define dso_local spir_kernel void @k(float addrspace(1)* %out, float %a, i32 %n) local_unnamed_addr #0 {
  %1 = tail call spir_func i64 @_Z13get_global_idj(i32 noundef 0) #4
  %2 = trunc i64 %1 to i32
  %3 = fadd float %a, 1.000000e+00
  %4 = fmul fast float %3, %a
  %5 = fneg float %4
  %6 = fcmp olt float %5, %a
  %7 = select i1 %6, float %5, float %a
  %8 = select i1 %6, i32 %2, i32 %n
  %9 = sitofp i32 %8 to float
  %10 = tail call float @llvm.fmuladd.f32(float %9, float %7, float %a)
  %11 = tail call spir_func float @_Z4sqrtf(float noundef %10) #5
  %12 = tail call spir_func float @_Z5rsqrtf(float noundef %11) #5
  %13 = fdiv float %12, %a, !fpmath !9
  %14 = udiv i32 %8, 3
  %15 = mul nsw i32 %14, %n
  %16 = zext i32 %15 to i64
  %17 = mul nuw i64 %16, 3528905107
  %18 = lshr i64 %17, 32
  %19 = add i32 %15, 7
  %20 = xor i32 %19, %n
  %21 = icmp ult i32 %20, %n
  br i1 %21, label %22, label %25

22:                                               ; preds = %0
  %23 = fadd <4 x float> zeroinitializer, zeroinitializer
  %24 = tail call spir_func float @_Z5clampfff(float noundef %13, float noundef 0.0, float noundef 1.0) #5
  br label %25

25:                                               ; preds = %22, %0
  %26 = phi float [ %24, %22 ], [ %13, %0 ]
  %27 = tail call spir_func i32 @_Z3minjj(i32 noundef %20, i32 noundef 5) #5
  tail call void @llvm.experimental.noalias.scope.decl(metadata !8)
  %28 = getelementptr inbounds float, float addrspace(1)* %out, i64 %1
  store float %26, float addrspace(1)* %28, align 4
  ret void
}

define dso_local spir_kernel void @k_tail(float %a) local_unnamed_addr #0 {
  %1 = fadd float %a, %a
  ret void
}
)LL";

PeakRates peaks_of(double float_op, double int_op, double mul, double mul64, double sqrt, double division)
{
    PeakRates peaks;
    peaks.ops_per_s = {float_op, int_op, mul, mul64, sqrt, division};
    return peaks;
}

} // namespace

TEST_CASE("the IR counter counts a hand-written kernel exactly, class by class, and nothing of the next function")
{
    const OpCounts counts = count_kernel_ops(hand_written_ll, "k");
    CAPTURE(counts.other_text());
    CHECK(counts.other.empty());
    // fadd, fmul, fneg, fcmp, float select, sitofp, fmuladd, 4 lanes of fadd, clamp (2)
    CHECK(counts[OpClass::float_op] == 13);
    CHECK(counts[OpClass::int_op] == 6);  // int select, lshr, add, xor, icmp, min
    CHECK(counts[OpClass::int_mul] == 1);
    CHECK(counts[OpClass::int_mul_wide] == 1);
    CHECK(counts[OpClass::sqrt] == 2);
    CHECK(counts[OpClass::division] == 2);  // fdiv, udiv
    CHECK(counts.total() == 25);
    CHECK(count_kernel_ops(hand_written_ll, "k_tail")[OpClass::float_op] == 1);
    const OpCounts per_eight = counts.per(8);
    CHECK(per_eight[OpClass::float_op] == doctest::Approx(13.0 / 8));
}

TEST_CASE("an unknown call or opcode is counted as other, named, and fails the strict count")
{
    std::string ll = hand_written_ll;
    ll.replace(ll.find("@_Z4sqrtf"), 9, "@_Z3sinf");
    ll.replace(ll.find("%14 = udiv"), 10, "%14 = frobnicate");
    const OpCounts counts = count_kernel_ops(ll, "k");
    CHECK(counts.other.at("call _Z3sinf") == 1);
    CHECK(counts.other.at("frobnicate") == 1);
    CHECK(counts[OpClass::sqrt] == 1);
    try {
        count_kernel_ops_strict(ll, "k");
        FAIL("the strict count took an unknown call");
    } catch (const std::runtime_error& e) {
        CHECK(std::string(e.what()).find("_Z3sinf") != std::string::npos);
        CHECK(std::string(e.what()).find("frobnicate") != std::string::npos);
    }
    CHECK_THROWS_WITH_AS(count_kernel_ops(hand_written_ll, "ggx_sample_bulk"), doctest::Contains("@ggx_sample_bulk"),
                         std::runtime_error);
}

TEST_CASE("the roofline: max and sum over classes, bandwidth from the store-only kernel, % of the tighter limit")
{
    OpCounts counts;
    counts[OpClass::float_op] = 100;
    counts[OpClass::int_op] = 50;
    counts[OpClass::sqrt] = 2;
    const ComputeLimit limit = compute_limit(counts, peaks_of(100e9, 100e9, 0, 0, 10e9, 0));
    CHECK(limit.ns == doctest::Approx(1.0));  // float: 100 / 100e9 s
    CHECK(limit.binding == OpClass::float_op);
    CHECK(limit.sum_ns == doctest::Approx(1.7));  // 1.0 + 0.5 + 0.2
    counts[OpClass::division] = 1;  // a counted class without a peak
    CHECK_THROWS_WITH_AS(compute_limit(counts, peaks_of(100e9, 100e9, 0, 0, 10e9, 0)), doctest::Contains("div"),
                         std::invalid_argument);
    CHECK(stored_bytes_per_sample(BenchJob::write) == stored_bytes_per_sample(BenchJob::store));
    CHECK(stored_bytes_per_sample(BenchJob::furnace) == doctest::Approx(8.0 / GGX_FURNACE_PER_ITEM));
    CHECK_THROWS_AS(stored_bytes_per_sample(BenchJob::world), std::invalid_argument);
    CHECK(bandwidth_limit_ns(16, 2.0) == doctest::Approx(2.0));
    CHECK(bandwidth_limit_ns(1, 2.0) == doctest::Approx(0.125));
    CHECK(percent_of_limit(2.0, 4.0) == doctest::Approx(50.0));
    CHECK_THROWS_WITH_AS(percent_of_limit(2.0, 0.0), doctest::Contains("measured"), std::invalid_argument);
}

TEST_CASE("a row's limit is the tighter of compute and bandwidth, and its percentage goes into the CSV")
{
    LimitReport report;
    report.has_peaks = true;
    report.peaks = peaks_of(100e9, 100e9, 100e9, 100e9, 10e9, 10e9);
    LimitRow store, caps;
    store.row.method = "all", store.row.precision = "store-only", store.row.job = "write", store.row.timing.median = 1.0;
    caps.row.method = "caps", caps.row.precision = "precise", caps.row.job = "write", caps.row.timing.median = 4.0;
    caps.ops = OpCounts{};
    (*caps.ops)[OpClass::float_op] = 200;  // 2 ns at 100 G/s: tighter than the store's 1 ns
    report.rows = {store, caps};
    std::optional<RowLimit> limit = row_limit(report.rows[1], report);
    REQUIRE(limit);
    CHECK(limit->compute_binds);
    CHECK(limit->percent == doctest::Approx(50.0));
    report.rows[1].row.timing.median = 4.1;
    CHECK(row_limit(report.rows[1], report)->percent == doctest::Approx(200.0 / 4.1));
    const std::string csv = limits_csv(report);
    const std::string caps_line = csv.substr(csv.find("\ncaps,") + 1);
    CHECK(caps_line.find(",float,") != std::string::npos);
    CHECK(caps_line.substr(0, caps_line.find('\n')).substr(caps_line.rfind(',', caps_line.find('\n')) + 1) ==
          "48.7805");  // percent_of_limit, what bench/check_targets.py reads
    CHECK(csv.find("all,store-only,write,1,") != std::string::npos);
}

TEST_CASE("the peak probe's kernels do the operations the probe divides by: nothing folded away")
{
    const ClangTool clang = find_clang();
    if (!ggxtest::skip_unless(!clang.path.empty(), "needs clang 15 to compile kernels to IR: " + clang.unavailable))
        return;
    const std::string ll = compile_to_ir(clang, {{peak_probe_source(), "-cl-fp32-correctly-rounded-divide-sqrt"}}, 1)[0];
    for (OpClass c : all_op_classes) {
        CAPTURE(std::string(op_class_name(c)));
        const OpCounts counts = count_kernel_ops_strict(ll, peak_kernel_name(c));
        // The chains' steps, plus a few for the start values and the final sum.
        CHECK(counts[c] >= peak_ops_per_item(c));
        CHECK(counts[c] <= peak_ops_per_item(c) + 20);
        // The rest: start values and sum, each int mul64 step's shift (its high half) and each int
        // mul step's xor (what keeps the chain from folding into a power).
        const bool one_more_per_step = c == OpClass::int_mul_wide || c == OpClass::int_mul;
        const double extra = one_more_per_step ? peak_ops_per_item(c) : 0;
        CHECK(counts.total() <= peak_ops_per_item(c) + extra + 30);
    }
}

// A step that reads its chain twice (x = x * x) makes an expression whose paths double with every
// step; NVIDIA's compiler spent minutes on one.  Each step must read its chain's value once.
TEST_CASE("each step of the peak probe reads its chain's value once")
{
    const std::string& source = peak_probe_source();
    const std::regex step(R"(#define (\w+)_STEP\(x\) x = ([^;]*);)");
    const std::regex chain_value(R"(\bx\b)");
    int steps = 0;
    for (std::sregex_iterator it(source.begin(), source.end(), step), end; it != end; ++it, ++steps) {
        const std::string right = (*it)[2];
        CAPTURE(it->str());
        CHECK(std::distance(std::sregex_iterator(right.begin(), right.end(), chain_value), std::sregex_iterator()) == 1);
    }
    CHECK(steps == int(std::size(all_op_classes)));
}

TEST_CASE("a child past its time limit is stopped and named; the peak rates travel from the child as text")
{
    const auto start = std::chrono::steady_clock::now();
    std::string message;
    try {
        run_child("/bin/sleep", {"30"}, 0.5);
    } catch (const ChildTimedOut& e) {
        message = e.what();
    }
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(10));
    CHECK(message == "`/bin/sleep 30` ran past its limit of 1 s and was stopped");
    CHECK(exited_ok(run_child("/bin/sleep", {"0"}, 5).status));  // control: within its limit

    PeakRates peaks;
    for (OpClass c : all_op_classes)
        peaks.ops_per_s[static_cast<std::size_t>(c)] = 1e9 + 12345.678 * static_cast<int>(c);
    peaks.seconds = 1.25;
    const PeakRates back = parse_peak_rates(peak_rates_text(peaks));
    CHECK(back.ops_per_s == peaks.ops_per_s);
    CHECK(back.seconds == peaks.seconds);
    CHECK_THROWS_AS(parse_peak_rates("peak_float 1e9\n"), std::runtime_error);
}

TEST_CASE("`ggx-limits --peak-probe`, the tool's child, prints every class's rate")
{
    const ChildOutput child = run_child(ggxtest::limits_binary(), {"--peak-probe"}, 120);
    CAPTURE(child.err);
    REQUIRE(exited_ok(child.status));
    const PeakRates peaks = parse_peak_rates(child.out);
    for (OpClass c : all_op_classes)
        CHECK(peaks[c] > 1e6);
    const ChildOutput help = run_child(ggxtest::limits_binary(), {"--help"}, 60);
    CHECK(help.out.find("--methods") != std::string::npos);
    CHECK(help.out.find("--peak-probe") == std::string::npos);  // internal: not listed
}

TEST_CASE("every bench kernel (method x write, furnace x precision) has only operations of known classes")
{
    const ClangTool clang = find_clang();
    if (!ggxtest::skip_unless(!clang.path.empty(), "needs clang 15 to compile kernels to IR: " + clang.unavailable))
        return;
    ggxcl::Sampler sampler;
    const std::unique_ptr<ggxcl::benchmark::DeviceJobs> jobs = ggxcl::benchmark::device_jobs(sampler, 1024, {});
    std::vector<IrRequest> requests;
    std::vector<ggxcl::benchmark::ProgramText> programs;
    for (ggxcl::Precision precision : ggxcl::all_precisions)
        for (ggxcl::Method method : ggxcl::all_methods) {
            ggxcl::SampleParams p;
            p.method = method;
            p.precision = precision;
            p.alpha_x = p.alpha_y = 0.3f;
            p.view = ggxcl::view_from_angles(60.0, 0.0);
            programs.push_back(*jobs->program(ggxcl::benchmark::Job::write, p));
            programs.push_back(*jobs->program(ggxcl::benchmark::Job::furnace, p));
        }
    CHECK_FALSE(jobs->program(ggxcl::benchmark::Job::world, ggxcl::SampleParams{}));  // only what clang counts
    for (const auto& program : programs)
        requests.push_back({ggxcl::kernel_source(program.file), program.options});
    const std::vector<std::string> ll = compile_to_ir(clang, requests, 2);
    for (std::size_t k = 0; k < programs.size(); ++k) {
        CAPTURE(programs[k].options);
        const OpCounts counts = count_kernel_ops(ll[k], programs[k].kernel);
        CHECK_MESSAGE(counts.other.empty(), counts.other_text());
        CHECK(counts[OpClass::float_op] > 0);
        CHECK(counts[OpClass::int_mul_wide] >= 10);  // Philox2x32-10: a 64-bit product per round
    }
}

// Rates only: which class is faster is a timing, which a loaded machine can turn around (CI once
// measured float below division with other suites on both cores); the measured peaks are in
// docs/COST-PROBES.md.
TEST_CASE("the peak probe measures positive finite rates on the device")
{
    ggxcl::Sampler sampler;
    const PeakRates peaks = measure_peaks(sampler);
    for (OpClass c : all_op_classes) {
        CAPTURE(std::string(op_class_name(c)));
        CHECK(std::isfinite(peaks[c]));
        CHECK(peaks[c] > 1e6);
    }
    CHECK(peaks.seconds > 0);
}

TEST_CASE("ggx-limits reports each row against its limits, and without a compiler the compute limit unavailable")
{
    const ggxtest::ScratchFolder dir("bench-limits");
    const std::string command = ggxtest::limits_binary() + " --methods caps,heitz -n 2^14 --repeats 5 --csv " +
                                (dir / "l.csv").string() + " --markdown " + (dir / "L.md").string();
    const ClangTool clang = find_clang();
    if (!clang.path.empty()) {
        ggxtest::Run run = ggxtest::run_ggx("{ " + command + " >" + (dir / "out.md").string() + "; }", dir / "stderr.txt",
                                            false);
        CAPTURE(run.err);
        REQUIRE(run.status == 0);
        const std::string csv = read_all(dir / "l.csv");
        CHECK(csv.rfind("method,precision,job,ns_median", 0) == 0);
        int limited = 0;
        for (const char* row : {"\ncaps,precise,write,", "\ncaps,precise,furnace,", "\nheitz,precise,write,",
                                "\nheitz,precise,furnace,"}) {
            CAPTURE(row);
            REQUIRE(csv.find(row) != std::string::npos);
            const std::string line = csv.substr(csv.find(row) + 1, csv.find('\n', csv.find(row) + 1) - csv.find(row) - 1);
            limited += std::stod(line.substr(line.rfind(',') + 1)) > 0.0;  // percent_of_limit
        }
        CHECK(limited == 4);
        const std::string md = read_all(dir / "L.md");
        CHECK(md == read_all(dir / "out.md"));  // printed and written alike
        for (const char* part : {"## How close to this device's limits", "| heitz | furnace |", "Peaks of this device",
                                 "Operations per sample by class"})
            CHECK(md.find(part) != std::string::npos);
    }
    ggxtest::Run run = ggxtest::run_ggx("GGXCL_CLANG=" + (dir / "no-clang").string() + " " + command,
                                        dir / "stderr.txt", false);
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::string md = read_all(dir / "L.md");
    CHECK(md.find("## How close to this device's limits") != std::string::npos);
    CHECK(md.find("Compute limits unavailable: no op counts (GGXCL_CLANG=") != std::string::npos);
    CHECK(md.find("| caps | write |") != std::string::npos);  // against the bandwidth limit alone
    CHECK(read_all(dir / "l.csv").find(",percent_of_limit") != std::string::npos);
    CHECK(ggxtest::run_ggx(ggxtest::limits_binary() + " --methods nonesuch", dir / "stderr.txt", false).status != 0);
}
