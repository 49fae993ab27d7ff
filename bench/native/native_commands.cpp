// native_commands.cpp - what ggx-native's commands run and print.  The timing is the wall clock
// around each run: one warm-up run (seed 1), then `repeats` runs with seeds 2, 3, ...
#include "native_commands.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "native_world_inputs.hpp"

namespace ggxnative {

namespace {

std::vector<double> ns_per_sample(const std::function<void(std::uint64_t seed)>& run, std::uint64_t count,
                                  int repeats)
{
    run(1);
    std::vector<double> ns;
    for (int r = 0; r < repeats; ++r) {
        auto start = std::chrono::steady_clock::now();
        run(std::uint64_t(r) + 2);
        std::chrono::duration<double, std::nano> elapsed = std::chrono::steady_clock::now() - start;
        ns.push_back(elapsed.count() / double(count));
    }
    return ns;
}

void finish(std::FILE* out)
{
    if (std::fflush(out) != 0 || std::ferror(out))
        throw std::runtime_error(std::string("writing to stdout failed: ") + std::strerror(errno));
}

// One line per repeat, with enough digits to read back the same double.
void print_lines(const std::vector<double>& ns, std::FILE* out)
{
    for (double value : ns)
        std::fprintf(out, "%.17g\n", value);
    finish(out);
}

}  // namespace

void time_job(int method, Job job, const TimedRun& run, std::FILE* out)
{
    const std::size_t n = run.count;
    std::vector<float> m, pdf_m, o, normals, views;
    if (job == Job::write_m_pdf_m) {
        m.resize(3 * n);
        pdf_m.resize(n);
    }
    if (job == Job::world_space_o) {
        o.resize(3 * n);
        world_inputs(run.count, normals, views);
    }
    const Buffers buffers{m.data(), pdf_m.data(), o.data(), normals.data(), views.data()};
    auto once = [&](std::uint64_t seed) {
        Setup setup{method, job, run.alpha, run.alpha, {run.view[0], run.view[1], run.view[2]}, seed, run.count,
                    run.threads};
        ggxnative::run(setup, buffers);
    };
    print_lines(ns_per_sample(once, run.count, run.repeats), out);
}

void time_vectorized(int method, const TimedRun& run, std::FILE* out)
{
    auto once = [&](std::uint64_t seed) {
        Setup setup{method, Job::furnace_sum, run.alpha, run.alpha, {run.view[0], run.view[1], run.view[2]}, seed,
                    run.count, run.threads};
        furnace_vectorized(setup);
    };
    print_lines(ns_per_sample(once, run.count, run.repeats), out);
}

void write_samples(const Setup& setup, std::FILE* out)
{
    std::vector<float> m(3 * setup.count), pdf_m(setup.count);
    run(setup, {m.data(), pdf_m.data()});
    if (std::fwrite(m.data(), sizeof(float), m.size(), out) != m.size() ||
        std::fwrite(pdf_m.data(), sizeof(float), pdf_m.size(), out) != pdf_m.size())
        throw std::runtime_error(std::string("writing to stdout failed: ") + std::strerror(errno));
    finish(out);
}

}  // namespace ggxnative
