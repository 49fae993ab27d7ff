// test_furnace.cpp - the fused white-furnace estimator (Backend::furnace, on
// the back end of GGX_TEST_API: CTest runs it on OpenCL and on Vulkan):
// its sums are those of the weights the bulk kernel stores for the same
// samples (any count, also not a multiple of the work-group size), its
// mean is the reference albedo within 4 standard errors for every method in
// every precision mode; a view opposite the normal is refused for the
// samplers of visible normals, and ndf reflects nothing there (sums 0); a
// dielectric's sums are bit-identical whatever the chunk size splits the
// range into, and a range's halves sum to the whole.
// Negative control: a range shifted by one sample does not give the same sums.
#include <doctest/doctest.h>

#include <cmath>

#include "backend_fixture.hpp"
#include "bit_compare.hpp"
#include "device_fixture.hpp"

namespace {

using ggxref::Method;

// The suite's back end; every case first checks that there is one (a skip where Vulkan is absent).
ggxcl::Backend& backend()
{
    return *ggxtest::test_backend();
}

struct StoredSums {
    double sum = 0, sum_of_squares = 0;
};

StoredSums stored_weight_sums(const ggxcl::SampleParams& p, const ggxcl::SampleRange& range)
{
    ggxcl::SampleSet s = backend().generate(p, range, {ggxcl::Field::weight});
    StoredSums sums;
    for (float w : s.weight) {
        sums.sum += w;
        sums.sum_of_squares += double(w) * w;
    }
    return sums;
}

// Float partial sums of 256 weights each, added in double: 1e-6 relative is ample.
bool same_sums(const ggxcl::FurnaceSums& fused, const StoredSums& stored)
{
    return std::fabs(fused.sum - stored.sum) <= 1e-6 * std::fabs(stored.sum) + 1e-6 &&
           std::fabs(fused.sum_of_squares - stored.sum_of_squares) <= 1e-6 * stored.sum_of_squares + 1e-6;
}

} // namespace

TEST_CASE("fused sums equal the sums of the stored weights, for any count")
{
    if (!ggxtest::test_backend())
        return;
    for (Method method : ggxref::all_methods)
        for (std::uint64_t count : {1ull, 255ull, 1000ull, 65536ull + 7}) {
            CAPTURE(ggxref::method_name(method));
            CAPTURE(count);
            ggxcl::SampleParams p =
                ggxtest::to_library(method, ggxtest::make_params(0.4, 0.4, 70.0), ggxcl::Precision::precise);
            ggxcl::FurnaceSums fused = backend().furnace(p, {5, 123, count});
            CHECK(fused.count == count);
            CHECK(same_sums(fused, stored_weight_sums(p, {5, 123, count})));
        }
}

TEST_CASE("fused mean is the reference albedo in every precision mode")
{
    if (!ggxtest::test_backend())
        return;
    const std::uint64_t count = 1u << 21;
    for (Method method : ggxref::all_methods)
        for (ggxcl::Precision precision : ggxtest::all_precisions)
            for (double theta : {0.0, 75.0}) {
                ggxref::Params params = ggxtest::make_params(0.6, 0.6, theta);
                ggxcl::FurnaceSums fused =
                    backend().furnace(ggxtest::to_library(method, params, precision), {11, 0, count});
                double albedo = ggxref::albedo(params);
                double standard_error = std::sqrt(fused.variance() / double(count));
                CAPTURE(ggxref::method_name(method));
                CAPTURE(theta);
                CAPTURE(fused.mean());
                CAPTURE(albedo);
                CHECK(std::fabs(fused.mean() - albedo) <= 4.0 * standard_error);
                CHECK(fused.variance() > 0.0);
            }
}

TEST_CASE("a view opposite the normal: refused for visible normals, nothing reflected for ndf (sums 0, not NaN)")
{
    if (!ggxtest::test_backend())
        return;
    for (Method method : {Method::heitz, Method::caps, Method::bounded, Method::ndf}) {
        ggxcl::SampleParams p = ggxtest::to_library(method, ggxtest::make_params(0.3, 0.3, 0.0), ggxcl::Precision::precise);
        CAPTURE(ggxref::method_name(method));
        for (const ggxcl::Vec3 view : {ggxcl::Vec3{0.0f, 0.0f, -1.0f}, ggxcl::view_from_angles(180.0, 0.0)}) {
            p.view = view;
            if (method != Method::ndf) {
                const std::string message = ggxtest::message_of<ggxcl::InvalidArgument>(
                    [&] { backend().furnace(p, {5, 0, 5000}); });
                CHECK(message.find("invalid view") != std::string::npos);
                CHECK(message.find("not opposite the normal") != std::string::npos);
                continue;
            }
            ggxcl::FurnaceSums fused = backend().furnace(p, {5, 0, 5000});
            CHECK(fused.sum == 0.0);
            CHECK(fused.sum_of_squares == 0.0);
        }
        p.view = ggxcl::view_from_angles(179.99, 0.0);  // still sees some microfacets
        CHECK_NOTHROW(backend().furnace(p, {5, 0, 5000}));
    }
}

TEST_CASE("the sums do not depend on how the chunk size splits the range")
{
    if (!ggxtest::test_backend())
        return;
    ggxcl::SampleParams p =
        ggxtest::to_library(Method::caps, ggxtest::make_params(0.5, 0.3, 50.0), ggxcl::Precision::precise);
    p.eta = 1.33f;
    const std::uint64_t samples = 200003;  // not a multiple of the samples per work-item
    const ggxcl::SampleRange range{3, 64, samples};
    const std::uint64_t chunk = backend().chunk_size();
    const ggxcl::FurnaceSums whole = backend().furnace(p, range);
    for (std::uint64_t size : {std::uint64_t(8), std::uint64_t(4096), std::uint64_t(50001)}) {
        CAPTURE(size);
        backend().set_chunk_size(size);
        const ggxcl::FurnaceSums split = backend().furnace(p, range);
        CHECK(split.sum == whole.sum);
        CHECK(split.sum_of_squares == whole.sum_of_squares);
        CHECK(split.reflected_sum == whole.reflected_sum);
    }
    backend().set_chunk_size(chunk);
    // Halves that start at a multiple of the samples per work-item sum to the whole.
    const std::uint64_t half = 100000;
    const ggxcl::FurnaceSums first = backend().furnace(p, {3, 64, half});
    const ggxcl::FurnaceSums second = backend().furnace(p, {3, 64 + half, samples - half});
    CHECK(std::fabs(first.sum + second.sum - whole.sum) <= 1e-9 * whole.sum);
}

TEST_CASE("negative control: a range shifted by one sample gives other sums")
{
    if (!ggxtest::test_backend())
        return;
    ggxcl::SampleParams p = ggxtest::to_library(Method::caps, ggxtest::make_params(0.4, 0.4, 70.0));
    ggxcl::FurnaceSums fused = backend().furnace(p, {5, 124, 1000});
    CHECK_FALSE(same_sums(fused, stored_weight_sums(p, {5, 123, 1000})));
}
