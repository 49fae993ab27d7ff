// test_backend_threads.cpp - the threading contract of a Backend (backend.hpp),
// on the back end of GGX_TEST_API (backend_fixture.hpp; CTest runs it on
// OpenCL and on Vulkan): 8 threads share one back end, each drawing in
// chunks (generate and generate_chunk_views), evaluating pdfs and BSDF
// values, binning a histogram and summing the furnace, all at once; every
// result equals, bit for bit, what one thread computes alone.  Control: two
// tasks' results differ, so the comparison can fail.
#include <doctest/doctest.h>

#include <exception>
#include <thread>

#include "backend_fixture.hpp"
#include "bit_compare.hpp"
#include "thread_tasks.hpp"

namespace {

using ggxcl::Field;
using ggxtest::same_bits;

constexpr int thread_count = 8, rounds = 2;
constexpr std::uint32_t samples = 3000;  // three chunks of 1024

using Task = ggxtest::ThreadTask;

Task task_of(int t)
{
    return ggxtest::thread_task(t, samples);
}

struct Results {
    ggxcl::SampleSet generated;
    std::vector<float> viewed_o, pdfs, values;
    std::vector<std::uint64_t> counts;
    ggxcl::FurnaceSums furnace;
};

Results run_task(ggxcl::Backend& backend, const Task& t)
{
    Results r;
    r.generated = backend.generate(t.params, t.range, ggxcl::FieldSet::all());
    backend.generate_chunk_views(t.params, t.range, {Field::o}, [&](const ggxcl::SampleView& chunk, std::uint64_t) {
        for (int c = 0; c < 3; ++c)
            r.viewed_o.insert(r.viewed_o.end(), chunk.o + c * chunk.stride, chunk.o + c * chunk.stride + chunk.count);
    });
    std::vector<ggxcl::Vec3> directions(samples);
    for (std::size_t j = 0; j < samples; ++j)
        directions[j] = r.generated.o_at(j);
    r.pdfs = backend.pdf(t.params, directions);
    r.values = backend.eval(t.params, directions);
    r.counts = backend.histogram(t.params, t.range, 16, 32).counts;
    r.furnace = backend.furnace(t.params, t.range);
    return r;
}

bool same_results(const Results& a, const Results& b)
{
    return same_bits(a.generated, b.generated) && same_bits(a.viewed_o, b.viewed_o) && same_bits(a.pdfs, b.pdfs) &&
           same_bits(a.values, b.values) && a.counts == b.counts && a.furnace.count == b.furnace.count &&
           a.furnace.sum == b.furnace.sum && a.furnace.sum_of_squares == b.furnace.sum_of_squares;
}

} // namespace

TEST_CASE("8 threads sharing one back end get the single-threaded results bit for bit")
{
    ggxcl::Backend* backend = ggxtest::test_backend();
    if (!backend)
        return;
    MESSAGE("back end: " << backend->device_label());
    const std::uint64_t saved = backend->chunk_size();
    backend->set_chunk_size(1024);
    std::vector<Results> alone;
    for (int t = 0; t < thread_count; ++t)
        alone.push_back(run_task(*backend, task_of(t)));
    CHECK_FALSE(same_results(alone[0], alone[1]));  // control

    std::vector<std::vector<Results>> together(thread_count);
    std::vector<std::exception_ptr> failures(thread_count);
    std::vector<std::thread> threads;
    for (int t = 0; t < thread_count; ++t)
        threads.emplace_back([&, t] {
            try {
                for (int k = 0; k < rounds; ++k)
                    together[t].push_back(run_task(*backend, task_of(t)));
            } catch (...) {
                failures[t] = std::current_exception();
            }
        });
    for (std::thread& thread : threads)
        thread.join();
    backend->set_chunk_size(saved);

    for (int t = 0; t < thread_count; ++t) {
        CAPTURE(t);
        if (failures[t])
            FAIL(ggxtest::message_of<std::exception>([&] { std::rethrow_exception(failures[t]); }));
        REQUIRE(together[t].size() == rounds);
        for (int k = 0; k < rounds; ++k) {
            CAPTURE(k);
            CHECK(same_results(together[t][k], alone[t]));
        }
    }
}
