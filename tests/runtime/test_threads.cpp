// test_threads.cpp - the thread-safety contract of README's "Threads"
// section: 8 threads share two Samplers on one context (one the other's
// programs), each drawing with generate (chunked, on the Sampler's own
// queue), enqueueing into its own buffers on its own queue, evaluating pdfs
// and summing furnace weights, all at once, and asking for the device
// headers and the device list; every result must equal, bit for bit, what one thread computes
// alone.  scripts/tsan.sh runs it under
// ThreadSanitizer.
#include <doctest/doctest.h>

#include <exception>
#include <thread>

#include "bit_compare.hpp"
#include "device_fixture.hpp"
#include "thread_tasks.hpp"

namespace {

using ggxcl::Field;
using ggxtest::same_bits;

constexpr int thread_count = 8, rounds = 3;
constexpr std::uint32_t samples = 5000;  // five chunks of 1024 in generate

using Task = ggxtest::ThreadTask;

Task task_of(int t)
{
    return ggxtest::thread_task(t, samples);
}

struct Results {
    ggxcl::SampleSet generated;
    std::vector<float> enqueued_m, enqueued_weight, pdfs;
    ggxcl::FurnaceSums furnace;
    std::string include_option, device_options, selected_device;
};

std::vector<float> read_floats(cl::CommandQueue& queue, const cl::Buffer& buffer, std::size_t count)
{
    std::vector<float> host(count);
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, count * sizeof(float), host.data());
    return host;
}

// One task: `drawing` generates on its own queue; `enqueueing` writes into
// fresh buffers on `queue` and evaluates the pdfs of the drawn directions.
Results run_task(ggxcl::Sampler& drawing, ggxcl::Sampler& enqueueing, cl::CommandQueue& queue, const Task& t)
{
    Results r;
    r.generated = drawing.generate(t.params, t.range, ggxcl::FieldSet::all());
    ggxcl::DeviceOutputs out;
    out.m = cl::Buffer(enqueueing.context(), CL_MEM_READ_WRITE, 3 * samples * sizeof(float));
    out.weight = cl::Buffer(enqueueing.context(), CL_MEM_READ_WRITE, samples * sizeof(float));
    enqueueing.enqueue(queue, t.params, t.range, out).wait();
    r.enqueued_m = read_floats(queue, out.m, 3 * samples);
    r.enqueued_weight = read_floats(queue, out.weight, samples);
    std::vector<ggxcl::Vec3> directions(samples);
    for (std::size_t j = 0; j < samples; ++j)
        directions[j] = r.generated.o_at(j);
    r.pdfs = enqueueing.pdf(t.params, directions);
    r.furnace = drawing.furnace(t.params, t.range);
    r.include_option = ggxcl::device_include_option();
    r.device_options = ggxcl::device_options(drawing.device());
    r.selected_device = ggxcl::select_device().label() + " of " + std::to_string(ggxcl::list_devices().size());
    return r;
}

bool same_results(const Results& a, const Results& b)
{
    return same_bits(a.generated, b.generated) && same_bits(a.enqueued_m, b.enqueued_m) &&
           same_bits(a.enqueued_weight, b.enqueued_weight) && same_bits(a.pdfs, b.pdfs) &&
           a.furnace.count == b.furnace.count && a.furnace.sum == b.furnace.sum &&
           a.furnace.sum_of_squares == b.furnace.sum_of_squares && a.include_option == b.include_option &&
           a.device_options == b.device_options && a.selected_device == b.selected_device;
}

} // namespace

TEST_CASE("8 threads sharing two samplers get the single-threaded results bit for bit")
{
    ggxcl::Sampler& first = ggxtest::sampler();
    ggxcl::Sampler second(first.context(), first.device());  // shares first's programs
    const std::uint64_t saved = first.chunk_size();
    first.set_chunk_size(1024);
    second.set_chunk_size(1024);

    std::vector<Results> alone;
    cl::CommandQueue main_queue(first.context(), first.device());
    for (int t = 0; t < thread_count; ++t)
        alone.push_back(run_task(first, second, main_queue, task_of(t)));

    // Round k of thread t draws with one sampler and enqueues with the other, alternating.
    std::vector<std::vector<Results>> together(thread_count);
    std::vector<std::exception_ptr> failures(thread_count);
    std::vector<std::thread> threads;
    for (int t = 0; t < thread_count; ++t)
        threads.emplace_back([&, t] {
            try {
                cl::CommandQueue queue(first.context(), first.device());
                for (int k = 0; k < rounds; ++k) {
                    const bool swap = (t + k) % 2 == 1;
                    together[t].push_back(run_task(swap ? second : first, swap ? first : second, queue, task_of(t)));
                }
            } catch (...) {
                failures[t] = std::current_exception();
            }
        });
    for (std::thread& thread : threads)
        thread.join();
    first.set_chunk_size(saved);

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
    CHECK(first.memory_retries() == 0);
    CHECK(second.memory_retries() == 0);
}

TEST_CASE("samplers of their own contexts come and go in two threads with the shared sampler's bits")
{
    // Each new context gets new kernels in each thread; those of a context
    // that has gone are released at the thread's next lease.
    const Task task = task_of(3);
    const ggxcl::SampleSet expected = ggxtest::sampler().generate(task.params, task.range, {Field::m, Field::weight});
    auto draw_with_fresh_samplers = [&] {
        for (int k = 0; k < 3; ++k) {
            ggxcl::Sampler fresh;  // GGXCL_DEVICE's device, as the shared sampler
            if (!same_bits(fresh.generate(task.params, task.range, {Field::m, Field::weight}), expected))
                throw std::runtime_error("a fresh sampler drew other bits");
        }
    };
    std::exception_ptr failure;
    std::thread other([&] {
        try {
            draw_with_fresh_samplers();
        } catch (...) {
            failure = std::current_exception();
        }
    });
    CHECK_NOTHROW(draw_with_fresh_samplers());
    other.join();
    CHECK(!failure);
}
