// thread_tasks.hpp - the requests the threading suites (test_threads,
// test_backend_threads) give their threads: each its own method,
// roughness, view, sequence and range, so that mixed-up results show.
#pragma once

#include <cstdint>

#include <ggxcl/ggxcl.hpp>

namespace ggxtest {

struct ThreadTask {
    ggxcl::SampleParams params;
    ggxcl::SampleRange range;
};

// Task t of `samples` samples.
inline ThreadTask thread_task(int t, std::uint64_t samples)
{
    ThreadTask task;
    task.params.method = ggxcl::all_methods[t % ggxcl::all_methods.size()];
    task.params.alpha_x = 0.1f + 0.1f * float(t);
    task.params.alpha_y = task.params.method == ggxcl::Method::caps_iso ? task.params.alpha_x : 0.3f;
    task.params.view = ggxcl::view_from_angles(10.0 * t, 40.0 * t);
    task.params.sequence = t % 2 ? ggxcl::Sequence::sobol : ggxcl::Sequence::philox;
    task.range = {std::uint64_t(t + 1), 1000ull * std::uint64_t(t), samples};
    return task;
}

} // namespace ggxtest
