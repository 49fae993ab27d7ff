// ggx_native_main.cpp - ggx-native: the native C++ baseline of `ggx bench` as a program of its
// own.  The baseline is compiled -march=native; keeping it out of `ggx` (which runs it as a
// child process) keeps `ggx` and libggxcl runnable on any x86-64, and a baseline built for a
// newer CPU than the one it runs on costs the bench its native rows, not the whole run.
//
//   ggx-native time METHOD JOB COUNT THREADS REPEATS ALPHA VX VY VZ
//   ggx-native vectorized METHOD COUNT THREADS REPEATS ALPHA VX VY VZ
//   ggx-native write METHOD ALPHA_X ALPHA_Y VX VY VZ SEED COUNT
//
// time and vectorized (the furnace job, its loop vectorized by the compiler) print REPEATS
// lines, each the ns per sample of one timed run; write puts
// the raw float32 m (3 x COUNT, planar) and pdf_m (COUNT) on stdout, on one thread.  METHOD and
// JOB are ggxnative's names (caps-iso, write_m_pdf_m, ...).  Exit status: 0 done, 1 runtime
// failure, 2 bad arguments (a line on stderr naming the argument, then the usage).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "native_arguments.hpp"
#include "native_commands.hpp"

namespace {

using namespace ggxnative;

const char* const usage =
    "usage: ggx-native time METHOD JOB COUNT THREADS REPEATS ALPHA VX VY VZ\n"
    "       ggx-native vectorized METHOD COUNT THREADS REPEATS ALPHA VX VY VZ\n"
    "       ggx-native write METHOD ALPHA_X ALPHA_Y VX VY VZ SEED COUNT\n";

constexpr std::uint64_t max_count = 1u << 28;

// COUNT THREADS REPEATS ALPHA VX VY VZ, from a[0].
TimedRun timed_run(const std::string* a)
{
    TimedRun run{};
    run.count = parse_whole("COUNT", a[0], 1, max_count);
    run.threads = int(parse_whole("THREADS", a[1], 1, 256));
    run.repeats = int(parse_whole("REPEATS", a[2], 1, 1001));
    run.alpha = parse_float("ALPHA", a[3], 1e-30f, 1e30f);
    parse_view(a[4], a[5], a[6], run.view);
    return run;
}

int dispatch(const std::vector<std::string>& a)
{
    const std::string command = a.empty() ? "" : a[0];
    if (command == "time" && a.size() == 10) {
        time_job(parse_method(a[1]), parse_job(a[2]), timed_run(&a[3]), stdout);
        return 0;
    }
    if (command == "vectorized" && a.size() == 9) {
        time_vectorized(parse_method(a[1]), timed_run(&a[2]), stdout);
        return 0;
    }
    if (command == "write" && a.size() == 9) {
        Setup setup{parse_method(a[1]), Job::write_m_pdf_m, 0, 0, {}, 0, 0, 1};
        setup.alpha_x = parse_float("ALPHA_X", a[2], 1e-30f, 1e30f);
        setup.alpha_y = parse_float("ALPHA_Y", a[3], 1e-30f, 1e30f);
        parse_view(a[4], a[5], a[6], setup.view);
        setup.seed = parse_whole("SEED", a[7], 0, ~std::uint64_t(0));
        setup.count = parse_whole("COUNT", a[8], 1, max_count);
        write_samples(setup, stdout);
        return 0;
    }
    if (command == "time" || command == "vectorized" || command == "write")
        throw UsageError(command + " takes " + (command == "time" ? "9" : "8") + " arguments, not " +
                         std::to_string(a.size() - 1));
    throw UsageError("COMMAND '" + command + "': time, vectorized or write");
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        return dispatch(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const UsageError& e) {
        std::fprintf(stderr, "ggx-native: %s\n%s", e.what(), usage);
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ggx-native: error: %s\n", e.what());
        return 1;
    }
}
