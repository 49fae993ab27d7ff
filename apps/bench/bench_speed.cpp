// bench_speed.cpp - the bench's devices and their interleaved timings.
#include "bench_speed.hpp"

#include "report_text.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <random>

namespace ggxapp {

namespace {

constexpr std::uint64_t inputs_limit = 1u << 22;

// Whether a profiled duration can be the device time of a run that took `wall_ns` from launch to
// finish: positive, at least 1% of it (some drivers return constant or zero timestamps), and not
// longer than it by more than timer slack.
bool plausible_profile(double device_ns, double wall_ns)
{
    return device_ns > 0.0 && device_ns >= 0.01 * wall_ns && device_ns <= 1.5 * wall_ns + 1e6;
}

} // namespace

ggxcl::benchmark::JobInputs random_job_inputs(std::uint64_t count)
{
    const std::size_t n = std::size_t(std::min(count, inputs_limit));
    ggxcl::benchmark::JobInputs in;
    std::mt19937 rng(20231122);
    std::normal_distribution<float> gauss;
    for (std::size_t j = 0; j < n; ++j) {
        float normal[3], view[3];
        do {
            for (float& c : normal) c = gauss(rng);
            float len = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
            for (float& c : normal) c /= len;
        } while (normal[2] < -0.999f);
        float along;
        do {
            for (float& c : view) c = gauss(rng);
            float len = std::sqrt(view[0] * view[0] + view[1] * view[1] + view[2] * view[2]);
            for (float& c : view) c /= len;
            along = view[0] * normal[0] + view[1] * normal[1] + view[2] * normal[2];
            if (along < 0.0f)
                for (int c = 0; c < 3; ++c) view[c] -= 2.0f * along * normal[c];  // mirror into the upper side
            along = std::fabs(along);
        } while (along < 0.05f);
        in.world.normals.push_back({normal[0], normal[1], normal[2]});
        in.world.views.push_back({view[0], view[1], view[2]});
        in.per_sample.views.push_back({view[0], view[1], std::fabs(view[2])});  // the world job's view as a tangent-space one
    }
    std::mt19937 alpha_rng(5);
    std::uniform_real_distribution<float> alpha(0.05f, 1.0f);
    in.per_sample.alphas.resize(n);
    for (int c = 0; c < 2; ++c)  // the alpha_x plane, then the alpha_y plane
        for (std::size_t j = 0; j < n; ++j)
            in.per_sample.alphas[j][c] = alpha(alpha_rng);
    return in;
}

std::string job_name(BenchJob job)
{
    switch (job) {
    case BenchJob::write: return "write";
    case BenchJob::write_o: return "write-o";
    case BenchJob::furnace: return "furnace";
    case BenchJob::world: return "world";
    case BenchJob::per_sample: return "per-sample";
    case BenchJob::store: return "store";
    }
    return "?";
}

Timing summarize(std::vector<double> ns)
{
    std::sort(ns.begin(), ns.end());
    return {ns[ns.size() / 2], ns.front(), ns.back()};
}

std::string timing_text(const Timing& t, int digits)
{
    return fixed(t.median, digits) + " (" + fixed(t.low, digits) + "–" + fixed(t.high, digits) + ")";
}

double wall_ns_per_sample(const std::function<void()>& call, std::uint64_t count)
{
    const auto start = std::chrono::steady_clock::now();
    call();
    return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / double(count);
}

BenchDevice open_bench_device(const ApiChoice& choice, std::uint32_t count, const ggxcl::benchmark::JobInputs& inputs)
{
    BenchDevice device{choice, choice.open(), nullptr, {}};
    device.jobs = ggxcl::benchmark::device_jobs(*device.backend, count, inputs);
    return device;
}

std::vector<Timing> time_interleaved(const std::vector<BenchTask>& tasks, int repeats)
{
    for (const BenchTask& task : tasks)
        task.device->jobs->run(task.job, task.params, 1);  // warm-up: build and compile
    std::vector<std::vector<double>> profiled(tasks.size()), wall(tasks.size());
    // Broken timestamps fail every run; a loaded machine only delays some launches past 100x their
    // kernel (small runs): per device, the majority decides.
    struct Plausibility {
        int implausible = 0, runs = 0;
        std::string first;
    };
    std::map<BenchDevice*, Plausibility> devices;
    for (int r = 0; r < repeats; ++r)
        for (std::size_t t = 0; t < tasks.size(); ++t) {
            const BenchTask& task = tasks[t];
            const ggxcl::benchmark::RunTime time = task.device->jobs->run(task.job, task.params, std::uint64_t(r) + 2);
            const double samples = double(task.device->jobs->samples(task.job));
            Plausibility& p = devices[task.device];
            ++p.runs;
            if (!plausible_profile(time.device_ns, time.wall_ns) && p.implausible++ == 0)
                p.first = time.device_ns < 0 ? "the API gives no device time"
                                             : "a run profiled at " + duration_text(time.device_ns) + " took " +
                                                   duration_text(time.wall_ns);
            profiled[t].push_back(time.device_ns / samples);
            wall[t].push_back(time.wall_ns / samples);
        }
    for (auto& [device, p] : devices)
        device->clock =
            2 * p.implausible <= p.runs ? profiled_clock
                                        : "wall-clock (launch to finish: " + p.first + "; " +
                                              std::to_string(p.implausible) + " of " + std::to_string(p.runs) +
                                              " runs without a device time that can be right)";
    std::vector<Timing> timings;
    for (std::size_t t = 0; t < tasks.size(); ++t)
        timings.push_back(summarize(tasks[t].device->clock == profiled_clock ? profiled[t] : wall[t]));
    return timings;
}

} // namespace ggxapp
