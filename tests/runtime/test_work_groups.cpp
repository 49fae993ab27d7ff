// test_work_groups.cpp - determinism across work-group sizes:
// sample k is work-item k whatever the size of the groups, so every front
// end (host vectors, caller buffers, pdf, fused furnace, histogram) gives
// the same bits for sizes 1, 7 (not a power of two; whole groups plus a
// tail), 64 and the default; a size beyond the device's maximum is refused.
#include <doctest/doctest.h>

#include <cmath>

#include "bit_compare.hpp"
#include "device_fixture.hpp"

namespace {

using ggxtest::same_bits;

constexpr std::size_t sizes[] = {1, 7, 64};
constexpr ggxcl::SampleRange range{11, 1000, 3001};  // 3001 = 11 whole groups of 256 and a tail

ggxcl::SampleParams params_of(ggxcl::Method method)
{
    ggxcl::SampleParams p;
    p.method = method;
    p.alpha_x = 0.3f;
    p.alpha_y = method == ggxcl::Method::caps_iso ? 0.3f : 0.7f;
    p.view = ggxcl::view_from_angles(70, 40);
    p.precision = ggxcl::Precision::precise;
    return p;
}

// A sampler of its own, so that the shared one keeps the default size.
ggxcl::Sampler& own_sampler()
{
    static ggxcl::Sampler sampler(ggxtest::sampler().context(), ggxtest::sampler().device());
    return sampler;
}

std::vector<float> enqueued_o(ggxcl::Sampler& s, const ggxcl::SampleParams& p)
{
    cl::Buffer o(s.context(), CL_MEM_WRITE_ONLY, 3 * range.count * sizeof(float));
    ggxcl::DeviceOutputs out;
    out.o = o;
    s.enqueue(s.queue(), p, range, out).wait();
    std::vector<float> host(3 * range.count);
    s.queue().enqueueReadBuffer(o, CL_TRUE, 0, host.size() * sizeof(float), host.data());
    return host;
}

} // namespace

TEST_CASE("every method gives the same bits for every work-group size")
{
    ggxcl::Sampler& s = own_sampler();
    for (ggxcl::Method method : ggxcl::all_methods) {
        CAPTURE(ggxcl::method_name(method));
        ggxcl::SampleParams p = params_of(method);
        s.set_work_group_size(0);
        CHECK(s.work_group_size() == ggxtest::sampler().work_group_size());
        ggxcl::SampleSet expected = s.generate(p, range, ggxcl::FieldSet::all());
        std::vector<float> expected_o = enqueued_o(s, p);
        CHECK(same_bits(expected.o, expected_o));
        for (std::size_t size : sizes) {
            CAPTURE(size);
            s.set_work_group_size(size);
            CHECK(s.work_group_size() == size);
            CHECK(same_bits(expected, s.generate(p, range, ggxcl::FieldSet::all())));
            CHECK(same_bits(expected_o, enqueued_o(s, p)));
        }
    }
    s.set_work_group_size(0);
}

TEST_CASE("pdf, furnace and histogram give the same results for every work-group size")
{
    ggxcl::Sampler& s = own_sampler();
    ggxcl::SampleParams p = params_of(ggxcl::Method::caps);
    std::vector<ggxcl::Vec3> directions;
    for (int k = 0; k < 999; ++k)
        directions.push_back(ggxcl::view_from_angles(k % 90, std::fmod(7.0 * k, 360.0)));
    s.set_work_group_size(0);
    std::vector<float> pdf = s.pdf(p, directions);
    ggxcl::FurnaceSums furnace = s.furnace(p, {3, 0, 100003});
    ggxcl::Histogram histogram = s.histogram(p, {3, 0, 100003}, 16, 32);
    for (std::size_t size : {std::size_t(7), std::size_t(64)}) {
        CAPTURE(size);
        s.set_work_group_size(size);
        CHECK(same_bits(pdf, s.pdf(p, directions)));
        ggxcl::FurnaceSums again = s.furnace(p, {3, 0, 100003});
        CHECK(again.sum == furnace.sum);
        CHECK(again.sum_of_squares == furnace.sum_of_squares);
        CHECK(s.histogram(p, {3, 0, 100003}, 16, 32).counts == histogram.counts);
    }
    s.set_work_group_size(0);
}

TEST_CASE("a work-group size beyond the device's maximum is refused, naming the range")
{
    ggxcl::Sampler& s = own_sampler();
    std::size_t most = s.device().getInfo<CL_DEVICE_MAX_WORK_GROUP_SIZE>();
    std::string message =
        ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.set_work_group_size(most + 1); });
    CHECK(message.find("work-group size '" + std::to_string(most + 1) + "'") != std::string::npos);
    CHECK(message.find("1 .. " + std::to_string(most)) != std::string::npos);
    CHECK(s.work_group_size() == ggxtest::sampler().work_group_size());  // unchanged
}
