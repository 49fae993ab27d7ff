// test_small_batches.cpp - what a renderer enqueueing many small batches
// relies on: every Sampler on one context shares its programs (a second
// Sampler builds nothing), warm_up() builds the variant a later enqueue and
// generate use, and several threads enqueueing on one Sampler at once (each
// on its own queue) get exactly the samples generate() gives.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <thread>

#include "bit_compare.hpp"
#include "device_fixture.hpp"

namespace {

using ggxcl::Field;
using ggxtest::same_bits;

ggxcl::SampleParams batch_params()
{
    return {ggxcl::Method::caps, 0.35f, 0.2f, ggxcl::view_from_angles(40, 10)};
}

struct Batch {
    ggxcl::DeviceOutputs out;
    std::uint32_t count;
};

Batch make_batch(const ggxcl::Sampler& s, std::uint32_t count)
{
    Batch b{{}, count};
    b.out.m = cl::Buffer(s.context(), CL_MEM_READ_WRITE, 3 * count * sizeof(float));
    b.out.pdf_m = cl::Buffer(s.context(), CL_MEM_READ_WRITE, count * sizeof(float));
    return b;
}

ggxcl::SampleSet read_batch(cl::CommandQueue& queue, const Batch& b)
{
    ggxcl::SampleSet set;
    set.count = b.count;
    set.m.resize(3 * b.count);
    set.pdf_m.resize(b.count);
    queue.enqueueReadBuffer(b.out.m, CL_TRUE, 0, set.m.size() * sizeof(float), set.m.data());
    queue.enqueueReadBuffer(b.out.pdf_m, CL_TRUE, 0, set.pdf_m.size() * sizeof(float), set.pdf_m.data());
    return set;
}

} // namespace

TEST_CASE("Samplers on one context share their programs; another context does not")
{
    ggxcl::Sampler first;
    first.generate(batch_params(), {5, 0, 1000}, {Field::m});
    const std::size_t built = first.programs_built();
    REQUIRE(built >= 1);
    ggxcl::Sampler second(first.context(), first.device());
    CHECK(second.programs_built() == built);  // nothing built by the second, yet all there
    second.generate(batch_params(), {5, 0, 1000}, {Field::m});
    CHECK(first.programs_built() == built);
    ggxcl::Sampler elsewhere;  // a context of its own
    CHECK(elsewhere.programs_built() == 0);
}

TEST_CASE("warm_up builds the variant that enqueue and generate then use, with the same bits")
{
    ggxcl::Sampler s;
    s.warm_up(batch_params(), {Field::m, Field::pdf_m});
    CHECK(s.programs_built() == 1);
    Batch b = make_batch(s, 777);
    s.enqueue(s.queue(), batch_params(), {9, 123, b.count}, b.out).wait();
    ggxcl::SampleSet host = s.generate(batch_params(), {9, 123, b.count}, {Field::m, Field::pdf_m});
    CHECK(s.programs_built() == 1);  // no further build
    ggxcl::SampleSet device = read_batch(s.queue(), b);
    CHECK(same_bits(device.m, host.m));
    CHECK(same_bits(device.pdf_m, host.pdf_m));
    ggxcl::DeviceInputs per_sample_kinds;
    per_sample_kinds.view = cl::Buffer(s.context(), CL_MEM_READ_ONLY, 4);  // contents never read
    per_sample_kinds.views_above_horizon = true;
    s.warm_up(batch_params(), {Field::weight}, per_sample_kinds);
    CHECK(s.programs_built() == 2);
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.warm_up(batch_params(), ggxcl::FieldSet{}); })
              .find("fields") != std::string::npos);
}

TEST_CASE("threads enqueueing on one Sampler, each on its own queue, get generate's samples")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    const int threads = 4, batches = 40;
    const std::uint32_t count = 1000;
    std::vector<std::vector<ggxcl::SampleSet>> results(threads);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            cl::CommandQueue queue(s.context(), s.device());
            for (int k = 0; k < batches; ++k) {
                Batch b = make_batch(s, count);
                s.enqueue(queue, batch_params(), {7, std::uint64_t(t * batches + k) * count, count}, b.out);
                results[t].push_back(read_batch(queue, b));
            }
        });
    for (std::thread& thread : pool)
        thread.join();
    ggxcl::SampleSet all =
        s.generate(batch_params(), {7, 0, std::uint64_t(threads) * batches * count}, {Field::m, Field::pdf_m});
    int differ = 0;
    for (int t = 0; t < threads; ++t)
        for (int k = 0; k < batches; ++k) {
            const std::size_t first = std::size_t(t * batches + k) * count, n = all.count;
            const ggxcl::SampleSet& r = results[t][k];
            std::vector<float> pdf(all.pdf_m.begin() + first, all.pdf_m.begin() + first + count);
            bool same = same_bits(r.pdf_m, pdf);
            for (int c = 0; c < 3; ++c)
                same = same && std::equal(r.m.begin() + c * count, r.m.begin() + (c + 1) * count,
                                          all.m.begin() + c * n + first,
                                          [](float a, float b) { return std::memcmp(&a, &b, 4) == 0; });
            differ += !same;
        }
    CHECK(differ == 0);
    // Control: the comparison sees a batch shifted by one sample.
    std::vector<float> shifted(all.pdf_m.begin() + 1, all.pdf_m.begin() + 1 + count);
    CHECK(!same_bits(results[0][0].pdf_m, shifted));
}
