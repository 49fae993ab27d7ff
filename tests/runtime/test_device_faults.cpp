// test_device_faults.cpp - device memory exhaustion and a lost device,
// provoked on any device through GGXCL_INJECT_FAULT:
//  - out of memory: the host front ends (generate, pdf, furnace, histogram)
//    halve their chunk and go on, with the same bits (the same counts) as an
//    undisturbed run; below the smallest chunk the
//    error names CL_MEM_OBJECT_ALLOCATION_FAILURE;
//  - a lost device: DeviceLost naming CL_DEVICE_NOT_AVAILABLE, and a
//    ChunkSink has received only the whole chunks finished before;
//  - a malformed GGXCL_INJECT_FAULT is refused, naming the forms allowed.
#include <doctest/doctest.h>

#include <cstdlib>

#include "bit_compare.hpp"
#include "device_fixture.hpp"

namespace {

using ggxtest::message_of;
using ggxtest::same_bits;

// Sets GGXCL_INJECT_FAULT for the lifetime of the object.
struct InjectedFault {
    explicit InjectedFault(const char* spec) { ::setenv("GGXCL_INJECT_FAULT", spec, 1); }
    ~InjectedFault() { ::unsetenv("GGXCL_INJECT_FAULT"); }
};

ggxcl::SampleParams params_of(ggxcl::Method method)
{
    ggxcl::SampleParams p;
    p.method = method;
    p.alpha_x = p.alpha_y = 0.4f;
    p.view = ggxcl::view_from_angles(45, 10);
    return p;
}

ggxcl::Sampler& fresh_sampler()
{
    static ggxcl::Sampler sampler(ggxtest::sampler().context(), ggxtest::sampler().device());
    return sampler;
}

constexpr ggxcl::SampleRange range{8, 77, 300007};

} // namespace

TEST_CASE("out of device memory: smaller chunks, the same bits")
{
    ggxcl::Sampler& s = fresh_sampler();
    ggxcl::SampleParams p = params_of(ggxcl::Method::bounded);
    ggxcl::SampleSet expected = s.generate(p, range, ggxcl::FieldSet::all());
    ggxcl::FurnaceSums furnace = s.furnace(p, range);
    std::vector<ggxcl::Vec3> directions(expected.count);
    for (std::size_t j = 0; j < directions.size(); ++j)
        directions[j] = expected.o_at(j);
    std::vector<float> pdf = s.pdf(p, directions);
    ggxcl::Histogram histogram = s.histogram(p, range, 16, 32);

    std::uint64_t retries = s.memory_retries();
    InjectedFault fault("alloc-above=200000");  // 3 planes of 16384 samples fit, of 32768 do not
    CHECK(same_bits(expected, s.generate(p, range, ggxcl::FieldSet::all())));
    CHECK(s.memory_retries() - retries == 5);  // 300007 -> 150003 -> 75001 -> 37500 -> 18750 -> 9375
    CHECK(same_bits(pdf, s.pdf(p, directions)));
    ggxcl::FurnaceSums again = s.furnace(p, range);
    CHECK(again.sum == furnace.sum);
    CHECK(again.sum_of_squares == furnace.sum_of_squares);
    retries = s.memory_retries();
    ggxcl::Histogram histogram_again = s.histogram(p, range, 16, 32);
    CHECK(histogram_again.counts == histogram.counts);
    CHECK(histogram_again.non_finite == histogram.non_finite);
    if (s.device().getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU)  // bin indices of a pass: 4 bytes per sample
        CHECK(s.memory_retries() - retries == 3);                    // 300007 -> 150003 -> 75001 -> 37500
}

TEST_CASE("out of device memory even at the smallest chunk: an error naming it")
{
    ggxcl::Sampler& s = fresh_sampler();
    InjectedFault fault("alloc-above=1000");
    std::string message =
        message_of<ggxcl::ClError>([&] { s.generate(params_of(ggxcl::Method::caps), range, {ggxcl::Field::m}); });
    CHECK(message.find("CL_MEM_OBJECT_ALLOCATION_FAILURE") != std::string::npos);
    CHECK(message.find("chunks of 1024 samples (the smallest tried)") != std::string::npos);
}

TEST_CASE("a lost device: DeviceLost, and only the chunks finished before reach the sink")
{
    ggxcl::Sampler& s = fresh_sampler();
    s.set_chunk_size(1 << 16);
    ggxcl::SampleParams p = params_of(ggxcl::Method::heitz);
    ggxcl::SampleSet expected = s.generate(p, range, {ggxcl::Field::o});
    std::vector<float> received;
    std::uint64_t next = 0;
    auto sink = [&](const ggxcl::SampleSet& chunk, std::uint64_t offset) {
        CHECK(offset == next);
        next += chunk.count;
        received.insert(received.end(), chunk.o.begin(), chunk.o.begin() + chunk.count);  // x plane
    };
    InjectedFault fault("lost-after=2");
    std::string message = message_of<ggxcl::DeviceLost>([&] { s.generate_chunks(p, range, {ggxcl::Field::o}, sink); });
    CHECK(message.find("device was lost") != std::string::npos);
    CHECK(message.find("CL_DEVICE_NOT_AVAILABLE") != std::string::npos);
    CHECK(next == 2 << 16);
    CHECK(same_bits(received, std::vector<float>(expected.o.begin(), expected.o.begin() + next)));
    CHECK(message_of<ggxcl::DeviceLost>([&] { s.furnace(p, range); }).find("lost") != std::string::npos);
    s.set_chunk_size(1 << 20);
}

TEST_CASE("a lost device in a split over several samplers fails the whole job")
{
    ggxcl::Sampler& a = fresh_sampler();
    ggxcl::Sampler& b = ggxtest::sampler();
    InjectedFault fault("lost-after=3");
    std::uint64_t delivered = 0;
    auto sink = [&](const ggxcl::SampleSet& chunk, std::uint64_t) { delivered += chunk.count; };
    CHECK_THROWS_AS(ggxcl::generate_split({&a, &b}, params_of(ggxcl::Method::caps), range, {ggxcl::Field::m}, sink,
                                          1 << 14),
                    ggxcl::DeviceLost);
    CHECK(delivered < range.count);
}

TEST_CASE("a malformed GGXCL_INJECT_FAULT is refused")
{
    for (const char* spec : {"lost-after=", "alloc-above=-1", "alloc-above=1e6", "crash"}) {
        CAPTURE(spec);
        InjectedFault fault(spec);
        std::string message = message_of<ggxcl::InvalidArgument>(
            [&] { fresh_sampler().generate(params_of(ggxcl::Method::ndf), {1, 0, 10}, {ggxcl::Field::m}); });
        CHECK(message.find("GGXCL_INJECT_FAULT '" + std::string(spec) + "'") != std::string::npos);
        CHECK(message.find("alloc-above=BYTES or lost-after=LAUNCHES") != std::string::npos);
    }
}
