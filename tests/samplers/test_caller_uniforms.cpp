// test_caller_uniforms.cpp - the caller's own uniforms in place of the
// sequence (PerSampleInputs::uniforms, DeviceInputs::uniforms):
//  - fed the uniforms a sequence would give, every method returns that
//    sequence's samples bit for bit (generate on the host, enqueue into
//    the caller's buffers with a stride), and the u field echoes them;
//  - on the device, a uniform outside [0, 1) (1, -1, NaN, Inf, 1.5) gives
//    the fallback m = o = n, pdfs and weight 0 about the normal the method
//    works with, in both precision modes and in world space; the edges of
//    [0, 1) (0, -0, the smallest subnormal, the largest float below 1) give
//    the reference's sample;
//  - the host refuses bad uniforms with an error naming the first bad index;
//  - the fused estimator takes them too.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "bit_compare.hpp"
#include "sample_compare.hpp"

namespace {

using ggxcl::Field;
using ggxcl::Sequence;
using Pair = std::array<float, 2>;

ggxcl::SampleParams params_of(ggxcl::Method method, Sequence sequence = Sequence::philox)
{
    ggxcl::SampleParams p;
    p.method = method;
    p.alpha_x = 0.25f;
    p.alpha_y = method == ggxcl::Method::caps_iso ? 0.25f : 0.4f;
    p.view = ggxcl::view_from_angles(50, 30);
    if (method == ggxcl::Method::caps_iso)
        p.normal = ggxcl::unit_vector({0.3f, -0.2f, 0.9f});
    p.sequence = sequence;
    return p;
}

std::vector<Pair> sequence_uniforms(Sequence sequence, std::uint64_t stream, std::uint64_t first, std::uint64_t n)
{
    std::vector<Pair> u(n);
    for (std::uint64_t j = 0; j < n; ++j) {
        std::array<double, 2> d = ggxtest::reference_uniforms(sequence, stream, first + j);
        u[j] = {float(d[0]), float(d[1])};
    }
    return u;
}

// A buffer of `pairs` as two planes of `stride` floats.
cl::Buffer planar_buffer(const std::vector<Pair>& pairs, std::size_t stride)
{
    std::vector<float> planes(2 * stride, 0.5f);
    for (std::size_t j = 0; j < pairs.size(); ++j) {
        planes[j] = pairs[j][0];
        planes[stride + j] = pairs[j][1];
    }
    return cl::Buffer(ggxtest::sampler().context(), planes.begin(), planes.end(), false);
}

std::vector<float> read_floats(const cl::Buffer& buffer, std::size_t n)
{
    std::vector<float> host(n);
    ggxtest::sampler().queue().enqueueReadBuffer(buffer, CL_TRUE, 0, n * sizeof(float), host.data());
    return host;
}

// Every field of the samples drawn on the device from the uniforms in `pairs` by enqueue.
ggxcl::SampleSet enqueued(const ggxcl::SampleParams& p, const std::vector<Pair>& pairs, std::size_t stride)
{
    auto& s = ggxtest::sampler();
    ggxcl::DeviceOutputs out;
    for (Field f : ggxcl::all_fields)
        out.of(f) = cl::Buffer(s.context(), CL_MEM_READ_WRITE, ggxcl::field_columns(f) * stride * sizeof(float));
    ggxcl::DeviceInputs in;
    in.uniforms = planar_buffer(pairs, stride);
    s.enqueue(s.queue(), p, {0, 0, pairs.size()}, out, std::uint32_t(stride), in).wait();
    ggxcl::SampleSet set;
    set.count = pairs.size();
    for (Field f : ggxcl::all_fields) {
        std::vector<float> planes = read_floats(out.of(f), ggxcl::field_columns(f) * stride);
        for (int c = 0; c < ggxcl::field_columns(f); ++c)
            set.column_source(f).insert(set.column_source(f).end(), planes.begin() + c * stride,
                                        planes.begin() + c * stride + pairs.size());
    }
    return set;
}

} // namespace

TEST_CASE("the uniforms of a sequence, given by the caller, give that sequence's samples bit for bit")
{
    const std::uint64_t n = 3000, first = 777;
    for (ggxcl::Method method : ggxcl::all_methods)
        for (Sequence sequence : ggxcl::all_sequences) {
            CAPTURE(ggxcl::method_name(method));
            CAPTURE(ggxcl::sequence_name(sequence));
            ggxcl::SampleParams p = params_of(method, sequence);
            ggxcl::SampleSet drawn = ggxtest::sampler().generate(p, {9, first, n}, ggxcl::FieldSet::all());
            ggxcl::PerSampleInputs given;
            given.uniforms = sequence_uniforms(sequence, 9, first, n);
            // The caller's uniforms replace the sequence, whichever is set.
            ggxcl::SampleSet host = ggxtest::sampler().generate(params_of(method, Sequence::philox), {123, 0, n},
                                                                ggxcl::FieldSet::all(), given);
            CHECK(ggxtest::same_bits(drawn, host));
            CHECK(ggxtest::same_bits(drawn.u, host.u));
            ggxcl::SampleSet device = enqueued(p, given.uniforms, n + 100);
            CHECK(ggxtest::same_bits(drawn, device));
            CHECK(ggxtest::same_bits(drawn.u, device.u));
        }
}

TEST_CASE("uniforms outside [0, 1) give the fallback on the device; its edges give the reference's sample")
{
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float below_one = std::nextafter(1.0f, 0.0f), tiny = std::numeric_limits<float>::denorm_min();
    const std::vector<Pair> bad = {{1.0f, 0.5f}, {0.5f, 1.0f}, {-1.0f, 0.5f}, {0.5f, nan}, {-nan, 0.5f},
                                   {inf, 0.5f},  {0.5f, -inf}, {1.5f, 0.2f},  {0.3f, -tiny}};
    const std::vector<Pair> edges = {{0.0f, 0.0f}, {-0.0f, 0.5f}, {tiny, below_one}, {below_one, tiny},
                                     {below_one, below_one}, {0.5f, -0.0f}};
    std::vector<Pair> all = bad;
    all.insert(all.end(), edges.begin(), edges.end());
    for (ggxcl::Method method : ggxcl::all_methods)
        for (ggxcl::Precision precision : ggxtest::all_precisions)
            for (bool world : {false, true}) {
                if (world && method == ggxcl::Method::caps_iso)
                    continue;  // caps-iso is world space already
                ggxcl::SampleParams p = params_of(method);
                p.precision = precision;
                if (world) {
                    p.world_space = true;
                    p.alpha_y = p.alpha_x;
                    p.normal = ggxcl::unit_vector({-0.4f, 0.1f, 0.8f});
                }
                CAPTURE(ggxcl::method_name(method));
                CAPTURE(ggxcl::precision_name(precision));
                CAPTURE(world);
                ggxcl::SampleParams unit = ggxcl::normalized(p);
                const bool about_normal = world || method == ggxcl::Method::caps_iso;
                const ggxcl::Vec3 n = about_normal ? unit.normal : ggxcl::Vec3{0.0f, 0.0f, 1.0f};
                ggxcl::SampleSet s = enqueued(p, all, all.size());
                for (std::size_t j = 0; j < all.size(); ++j) {
                    CAPTURE(j);
                    ggxcl::Vec3 m = s.m_at(j), o = s.o_at(j);
                    bool fallback = m.x == n.x && m.y == n.y && m.z == n.z && o.x == n.x && o.y == n.y && o.z == n.z &&
                                    s.pdf_m[j] == 0.0f && s.pdf_o[j] == 0.0f && s.weight[j] == 0.0f;
                    CHECK(fallback == (j < bad.size()));
                    CHECK(std::memcmp(&s.u[j], &all[j][0], sizeof(float)) == 0);  // echoed as given, NaN included
                    CHECK(std::memcmp(&s.u[s.count + j], &all[j][1], sizeof(float)) == 0);
                    if (j >= bad.size())
                        CHECK((std::isfinite(m.x) && std::isfinite(o.z) && std::isfinite(s.pdf_o[j]) &&
                               std::isfinite(s.weight[j])));
                }
            }
}

// At the edges the maps are ill-conditioned (a cap's rim: the square root of
// a vanishing difference, then unstretched by 1/alpha), so the bound on the
// angle is 4 times the worst-sample bound of test_per_sample.
TEST_CASE("the edges of [0, 1) give the reference's sample")
{
    const double edge_angle_bound = 4 * ggxtest::angle_bound.maximum;
    const float below_one = std::nextafter(1.0f, 0.0f), tiny = std::numeric_limits<float>::denorm_min();
    const std::vector<Pair> edges = {{0.0f, 0.0f}, {0.0f, 0.25f}, {tiny, below_one}, {below_one, tiny},
                                     {below_one, below_one}, {0.5f, 0.0f}, {0.25f, below_one}};
    for (ggxref::Method method : ggxref::all_methods) {
        CAPTURE(std::string(ggxref::method_name(method)));
        double worst = 0.0;
        for (const ggxtest::Config& config : ggxtest::distribution_grid(method)) {
            ggxcl::PerSampleInputs given;
            given.uniforms = edges;
            ggxcl::SampleSet d = ggxtest::sampler().generate(ggxtest::to_library(method, config.params), {0, 0, edges.size()},
                                                             ggxcl::FieldSet::all(), given);
            for (std::size_t j = 0; j < edges.size(); ++j) {
                ggxref::Sample r = ggxref::sample(method, config.params, edges[j][0], edges[j][1]);
                ggxcl::Vec3 dm = d.m_at(j);
                double angle = ggxtest::angle_between({dm.x, dm.y, dm.z}, r.m);
                CAPTURE(config.label);
                CAPTURE(j);
                CHECK((std::isfinite(d.pdf_o[j]) && std::isfinite(d.weight[j])));
                CHECK(angle < edge_angle_bound);
                worst = std::max(worst, angle);
            }
        }
        MESSAGE(std::string(ggxref::method_name(method)) << ": worst angle at the edges " << worst << " rad");
    }
}

TEST_CASE("the host refuses uniforms outside [0, 1), naming the first bad index")
{
    auto& s = ggxtest::sampler();
    ggxcl::SampleParams p = params_of(ggxcl::Method::caps);
    ggxcl::PerSampleInputs given;
    given.uniforms.assign(10, {0.5f, 0.5f});
    given.uniforms[6] = {0.25f, 1.0f};
    given.uniforms[8] = {-0.5f, 0.0f};
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.generate(p, {0, 0, 10}, {Field::m}, given); }) ==
          "invalid uniforms[6] '0.25,1': allowed is two numbers in [0, 1)");
    given.uniforms[6] = {std::numeric_limits<float>::quiet_NaN(), 0.5f};
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.generate(p, {0, 0, 10}, {Field::m}, given); }) ==
          "invalid uniforms[6] 'nan,0.5': allowed is two numbers in [0, 1)");
    // Doubles become floats in [0, 1): rounded, but never up to 1 (control: a plain cast gives 1).
    CHECK(ggxcl::uniform_to_float(0.999999999) == std::nextafter(1.0f, 0.0f));
    CHECK(float(0.999999999) == 1.0f);
    CHECK(ggxcl::uniform_to_float(0.25) == 0.25f);
    CHECK(ggxcl::uniform_to_float(0.1) == 0.1f);
    given.uniforms.resize(9);
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.generate(p, {0, 0, 10}, {Field::m}, given); }) ==
          "invalid uniforms '9 entries': allowed is 0 (uniform) or one per sample (10)");
}

TEST_CASE("the fused estimator takes the caller's uniforms")
{
    auto& s = ggxtest::sampler();
    const std::uint64_t n = 4096;
    ggxcl::SampleParams p = params_of(ggxcl::Method::heitz, Sequence::sobol);
    std::vector<Pair> sobol = sequence_uniforms(Sequence::sobol, 2, 0, n);
    ggxcl::DeviceInputs in;
    in.uniforms = planar_buffer(sobol, n);
    std::size_t items = s.furnace_items(n);
    cl::Buffer sums(s.context(), CL_MEM_READ_WRITE, 2 * items * sizeof(float));
    s.enqueue_furnace(s.queue(), params_of(ggxcl::Method::heitz), {0, 0, n}, sums, in).wait();
    std::vector<float> partial = read_floats(sums, 2 * items);
    double given = 0.0;
    for (std::size_t k = 0; k < items; ++k)
        given += partial[k];
    ggxcl::FurnaceSums drawn = s.furnace(p, {2, 0, n});
    CHECK(given / n == doctest::Approx(drawn.mean()).epsilon(1e-6));
    // Control: the Philox stream of the same seed gives another estimate.
    CHECK(s.furnace(params_of(ggxcl::Method::heitz), {2, 0, n}).mean() != doctest::Approx(given / n).epsilon(1e-6));
}

TEST_CASE("enqueue refuses buffers smaller than their planes of the stride, naming them")
{
    auto& s = ggxtest::sampler();
    const std::uint32_t n = 1000, stride = 1024;
    ggxcl::DeviceOutputs out;
    out.m = cl::Buffer(s.context(), CL_MEM_READ_WRITE, 3 * stride * sizeof(float) - 4);
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] {
              s.enqueue(s.queue(), params_of(ggxcl::Method::caps), {0, 0, n}, out, stride);
          }) == "invalid outputs.m 'a buffer of 3071 floats with offset 0': allowed is offset + 3072 floats (3 planes "
                "of stride 1024) within the buffer");
    out.m = cl::Buffer(s.context(), CL_MEM_READ_WRITE, 3 * stride * sizeof(float));
    ggxcl::DeviceInputs in;
    in.uniforms = cl::Buffer(s.context(), CL_MEM_READ_ONLY, stride * sizeof(float));  // one plane of two
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] {
              s.enqueue(s.queue(), params_of(ggxcl::Method::caps), {0, 0, n}, out, stride, in);
          }).find("invalid inputs.uniforms 'a buffer of 1024 floats with offset 0'") == 0);
    in.uniforms = planar_buffer(sequence_uniforms(Sequence::philox, 0, 0, n), stride);  // control: big enough
    CHECK_NOTHROW(s.enqueue(s.queue(), params_of(ggxcl::Method::caps), {0, 0, n}, out, stride, in).wait());
}

TEST_CASE("enqueue_pdf and enqueue_furnace refuse buffers too small, naming them")
{
    auto& s = ggxtest::sampler();
    const std::uint32_t n = 1000;
    const ggxcl::SampleParams p = params_of(ggxcl::Method::caps);
    cl::Buffer directions(s.context(), CL_MEM_READ_ONLY, 3 * n * sizeof(float));
    cl::Buffer pdfs(s.context(), CL_MEM_READ_WRITE, n * sizeof(float));
    cl::Buffer short_directions(s.context(), CL_MEM_READ_ONLY, 2 * n * sizeof(float));
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.enqueue_pdf(s.queue(), p, n, short_directions, pdfs); })
              .find("invalid directions 'a buffer of 2000 floats with offset 0'") == 0);
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.enqueue_pdf(s.queue(), p, n, directions, pdfs, 1024); })
              .find("invalid directions 'a buffer of 3000 floats with offset 0': allowed is offset + 3072 floats") == 0);
    cl::Buffer short_pdfs(s.context(), CL_MEM_READ_WRITE, (n - 1) * sizeof(float));
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.enqueue_pdf(s.queue(), p, n, directions, short_pdfs); })
              .find("invalid pdf_out 'a buffer of 999 floats with offset 0'") == 0);
    std::vector<float> planes(3 * n, 0.0f);
    for (std::uint32_t j = 0; j < n; ++j)
        planes[2 * n + j] = 1.0f;  // control: +z, buffers big enough
    s.queue().enqueueWriteBuffer(directions, CL_TRUE, 0, planes.size() * sizeof(float), planes.data());
    CHECK_NOTHROW(s.enqueue_pdf(s.queue(), p, n, directions, pdfs).wait());

    const std::size_t items = s.furnace_items(n);
    cl::Buffer one_plane(s.context(), CL_MEM_READ_WRITE, items * sizeof(float));
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.enqueue_furnace(s.queue(), p, {0, 0, n}, one_plane); })
              .find("invalid sums") == 0);
    ggxcl::DeviceInputs in;
    in.uniforms = cl::Buffer(s.context(), CL_MEM_READ_ONLY, n * sizeof(float));  // one plane of two
    cl::Buffer sums(s.context(), CL_MEM_READ_WRITE, 2 * items * sizeof(float));
    CHECK(ggxtest::message_of<ggxcl::InvalidArgument>([&] { s.enqueue_furnace(s.queue(), p, {0, 0, n}, sums, in); })
              .find("invalid inputs.uniforms") == 0);
    CHECK_NOTHROW(s.enqueue_furnace(s.queue(), p, {0, 0, n}, sums).wait());  // control
}
