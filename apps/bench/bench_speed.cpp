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

ggxcl::Vec3 vec_at(const std::vector<float>& planes, std::size_t count, std::size_t j)
{
    return {planes[j], planes[count + j], planes[2 * count + j]};
}

} // namespace

void random_world_inputs(std::uint32_t count, std::vector<float>& normals, std::vector<float>& views)
{
    std::mt19937 rng(20231122);
    std::normal_distribution<float> gauss;
    normals.resize(3 * std::size_t(count));
    views.resize(3 * std::size_t(count));
    for (std::uint32_t j = 0; j < count; ++j) {
        float n[3], v[3];
        do {
            for (float& c : n) c = gauss(rng);
            float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (float& c : n) c /= len;
        } while (n[2] < -0.999f);
        float along;
        do {
            for (float& c : v) c = gauss(rng);
            float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            for (float& c : v) c /= len;
            along = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
            if (along < 0.0f)
                for (int c = 0; c < 3; ++c) v[c] -= 2.0f * along * n[c];  // mirror into the upper side
            along = std::fabs(along);
        } while (along < 0.05f);
        for (int c = 0; c < 3; ++c) {
            normals[c * std::size_t(count) + j] = n[c];
            views[c * std::size_t(count) + j] = v[c];
        }
    }
}

ggxcl::benchmark::JobInputs random_job_inputs(std::uint64_t count)
{
    const std::size_t n = std::size_t(std::min(count, inputs_limit));
    std::vector<float> normals, views;
    random_world_inputs(std::uint32_t(n), normals, views);
    ggxcl::benchmark::JobInputs in;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> alpha(0.05f, 1.0f);
    for (std::size_t j = 0; j < n; ++j) {
        in.world.normals.push_back(vec_at(normals, n, j));
        in.world.views.push_back(vec_at(views, n, j));
        ggxcl::Vec3 up = in.world.views.back();  // the world job's view read as a tangent-space view
        up.z = std::fabs(up.z);
        in.per_sample.views.push_back(up);
    }
    for (std::size_t j = 0; j < n; ++j)
        in.per_sample.alphas.push_back({alpha(rng), 0.0f});
    for (std::size_t j = 0; j < n; ++j)
        in.per_sample.alphas[j][1] = alpha(rng);
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

double wall_ns_per_sample(const std::function<void()>& call, std::uint64_t count)
{
    const auto start = std::chrono::steady_clock::now();
    call();
    return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / double(count);
}

BenchDevice open_bench_device(const ApiChoice& choice, std::uint32_t count)
{
    BenchDevice device{choice, choice.open(), nullptr, {}};
    device.jobs = ggxcl::benchmark::device_jobs(*device.backend, count, random_job_inputs(count));
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
