// test_offsets.cpp - the caller's buffers at offsets, which the kernels take
// as arguments (no sub-buffer, no copy): every output, every per-sample input,
// the pdf and eval kernels' directions and results, and the furnace's sums at
// odd offsets give the bits of the same call at offset 0 and leave every
// float outside their planes as it was; an offset past the buffer's end is
// refused naming the buffer.  (The C API's offsets: test_c_api.)
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "bit_compare.hpp"
#include "device_fixture.hpp"

namespace {

using ggxcl::Field;

constexpr std::uint32_t count = 1000, stride = 1003;  // a stride past count: gaps between the planes
constexpr float sentinel = -7777.0f;

cl::Buffer sentinels(const cl::Context& context, std::size_t floats)
{
    std::vector<float> values(floats, sentinel);
    return cl::Buffer(context, values.begin(), values.end(), false);
}

std::vector<float> read_all(cl::CommandQueue& queue, const cl::Buffer& buffer)
{
    std::vector<float> host(buffer.getInfo<CL_MEM_SIZE>() / sizeof(float));
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, host.size() * sizeof(float), host.data());
    return host;
}

// The planes of `planes` x `stride` floats from `offset` in `all`, each cut to count.
std::vector<float> planes_at(const std::vector<float>& all, std::size_t offset, int planes)
{
    std::vector<float> out;
    for (int c = 0; c < planes; ++c)
        out.insert(out.end(), all.begin() + std::ptrdiff_t(offset + c * stride),
                   all.begin() + std::ptrdiff_t(offset + c * stride + count));
    return out;
}

// Whether every float of `all` outside those planes is still the sentinel.
bool rest_untouched(const std::vector<float>& all, std::size_t offset, int planes)
{
    for (std::size_t k = 0; k < all.size(); ++k) {
        const bool inside = k >= offset && (k - offset) % stride < count && (k - offset) / stride < std::size_t(planes);
        if (!inside && all[k] != sentinel)
            return false;
    }
    return true;
}

// Per-sample views and alphas of the samples, planar at stride, from `offset` in new buffers.
ggxcl::DeviceInputs inputs_at(const cl::Context& context, std::size_t offset)
{
    std::vector<float> views(offset + 3 * stride, sentinel), alphas(offset + 2 * stride, sentinel);
    for (std::uint32_t j = 0; j < count; ++j) {
        const ggxcl::Vec3 v = ggxcl::unit_vector({0.3f + 1e-3f * float(j), -0.2f, 0.8f});
        views[offset + j] = v.x, views[offset + stride + j] = v.y, views[offset + 2 * stride + j] = v.z;
        alphas[offset + j] = 0.1f + 5e-4f * float(j), alphas[offset + stride + j] = 0.4f;
    }
    ggxcl::DeviceInputs in;
    in.view = cl::Buffer(context, views.begin(), views.end(), true);
    in.alpha = cl::Buffer(context, alphas.begin(), alphas.end(), true);
    in.view_offset = in.alpha_offset = offset;
    return in;
}

} // namespace

TEST_CASE("every output and input at an odd offset gives the bits at offset 0 and touches nothing else")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    cl::CommandQueue& queue = s.queue();
    for (ggxcl::Method method : {ggxcl::Method::caps, ggxcl::Method::ndf}) {
        ggxcl::SampleParams p{method, 0.3f, 0.5f, ggxcl::view_from_angles(40, 10)};
        CAPTURE(ggxcl::method_name(method));
        std::vector<std::vector<float>> at_zero, at_odd;
        for (std::size_t offset : {std::size_t(0), std::size_t(37)}) {
            ggxcl::DeviceOutputs out;
            for (Field f : ggxcl::all_fields) {
                out.of(f) = sentinels(s.context(), offset + std::size_t(f) + 3 * stride);
                out.offset_of(f) = offset + std::size_t(f);  // a different offset per field
            }
            s.enqueue(queue, p, {5, 11, count}, out, stride, inputs_at(s.context(), offset)).wait();
            for (Field f : ggxcl::all_fields) {
                const std::vector<float> all = read_all(queue, out.of(f));
                const int planes = ggxcl::field_columns(f, false);
                CHECK(rest_untouched(all, out.offset_of(f), planes));
                (offset == 0 ? at_zero : at_odd).push_back(planes_at(all, out.offset_of(f), planes));
            }
        }
        for (std::size_t f = 0; f < at_zero.size(); ++f)
            CHECK(ggxtest::same_bits(at_zero[f], at_odd[f]));
    }
}

TEST_CASE("pdf, eval and the furnace's sums at odd offsets give the bits at offset 0")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    cl::CommandQueue& queue = s.queue();
    const ggxcl::SampleParams p{ggxcl::Method::heitz, 0.4f, 0.2f, ggxcl::view_from_angles(60, 30)};
    const ggxcl::SampleSet drawn = s.generate(p, {3, 0, count}, {Field::o});
    std::vector<std::vector<float>> results[2];
    for (std::size_t offset : {std::size_t(0), std::size_t(13)}) {
        std::vector<float> directions(offset + 3 * stride, sentinel);
        for (int c = 0; c < 3; ++c)
            std::copy_n(drawn.o.data() + c * count, count, directions.begin() + std::ptrdiff_t(offset + c * stride));
        const cl::Buffer dirs(s.context(), directions.begin(), directions.end(), true);
        const ggxcl::DeviceArray pdfs{sentinels(s.context(), offset + 2 + stride), offset + 2};
        const ggxcl::DeviceArray values{sentinels(s.context(), offset + 4 + stride), offset + 4};
        s.enqueue_pdf(queue, p, count, {dirs, offset}, pdfs, stride).wait();
        s.enqueue_eval(queue, p, count, {dirs, offset}, values, stride).wait();
        const ggxcl::DeviceArray sums{sentinels(s.context(), offset + 2 * s.furnace_items(count)), offset};
        s.enqueue_furnace(queue, p, {3, 0, count}, sums).wait();
        for (const ggxcl::DeviceArray& array : {pdfs, values}) {
            const std::vector<float> all = read_all(queue, array.buffer);
            CHECK(rest_untouched(all, array.offset, 1));
            results[offset != 0].push_back(planes_at(all, array.offset, 1));
        }
        const std::vector<float> all_sums = read_all(queue, sums.buffer);
        CHECK(std::all_of(all_sums.begin(), all_sums.begin() + std::ptrdiff_t(offset),
                          [](float x) { return x == sentinel; }));
        results[offset != 0].emplace_back(all_sums.begin() + std::ptrdiff_t(offset), all_sums.end());
    }
    REQUIRE(results[0].size() == 3);
    for (std::size_t k = 0; k < 3; ++k)
        CHECK(ggxtest::same_bits(results[0][k], results[1][k]));
}

TEST_CASE("an offset past the end of a buffer is refused, naming the buffer, its size and the offset")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    const ggxcl::SampleParams p{ggxcl::Method::caps, 0.3f, 0.3f, ggxcl::view_from_angles(40, 10)};
    ggxcl::DeviceOutputs out;
    out.pdf_m = sentinels(s.context(), count + 10);
    out.pdf_m_offset = 11;
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.enqueue(s.queue(), p, {0, 0, count}, out); }) ==
          "invalid outputs.pdf_m 'a buffer of 1010 floats with offset 11': allowed is offset + 1000 floats (1 "
          "plane of stride 1000) within the buffer");
    out.pdf_m_offset = 10;
    CHECK_NOTHROW(s.enqueue(s.queue(), p, {0, 0, count}, out).wait());
}
