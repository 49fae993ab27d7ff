// test_albedo.cpp - the mean white-furnace weight of each method's device
// samples equals the directional albedo the reference integrates by
// quadrature, within 4 standard errors; a wrong albedo is rejected.
#include <doctest/doctest.h>

#include <cmath>

#include "device_fixture.hpp"

namespace {

using ggxref::Method;

constexpr std::uint64_t samples = 1000000;

struct Estimate {
    double mean = 0, standard_error = 0;
};

Estimate mean_weight(Method method, const ggxref::Params& params, std::uint64_t seed)
{
    ggxcl::SampleSet s = ggxtest::device_samples(method, params, seed, samples, {ggxcl::Field::weight});
    double sum = 0, sum2 = 0;
    for (float w : s.weight) {
        sum += w;
        sum2 += double(w) * w;
    }
    Estimate e;
    e.mean = sum / samples;
    double variance = std::max(0.0, sum2 / samples - e.mean * e.mean);
    e.standard_error = std::sqrt(variance / samples);
    return e;
}

std::vector<ggxref::Params> albedo_grid(Method method)
{
    std::vector<ggxref::Params> grid;
    for (double theta : {0.0, 45.0, 80.0}) {
        for (double alpha : {0.1, 0.5, 1.0})
            grid.push_back(ggxtest::make_params(alpha, alpha, theta));
        if (method != Method::caps_iso)
            grid.push_back(ggxtest::make_params(0.2, 0.7, theta, 30.0));
    }
    return grid;
}

void check_method(Method method)
{
    std::uint64_t seed = 300;
    for (const ggxref::Params& params : albedo_grid(method)) {
        Estimate e = mean_weight(method, params, ++seed);
        double albedo = ggxref::albedo(params);
        CAPTURE(ggxtest::describe(params));
        CAPTURE(e.mean);
        CAPTURE(e.standard_error);
        CAPTURE(albedo);
        CHECK(std::fabs(e.mean - albedo) <= 4.0 * e.standard_error);
    }
}

} // namespace

TEST_CASE("ndf: mean weight is the directional albedo") { check_method(Method::ndf); }
TEST_CASE("heitz: mean weight is the directional albedo") { check_method(Method::heitz); }
TEST_CASE("heitz2017: mean weight is the directional albedo") { check_method(Method::heitz2017); }
TEST_CASE("caps: mean weight is the directional albedo") { check_method(Method::caps); }
TEST_CASE("caps-iso: mean weight is the directional albedo") { check_method(Method::caps_iso); }
TEST_CASE("bounded: mean weight is the directional albedo") { check_method(Method::bounded); }

TEST_CASE("negative control: the albedo of the swapped roughness is rejected")
{
    ggxref::Params params = ggxtest::make_params(0.1, 0.8, 80.0, 30.0);
    ggxref::Params swapped = params;
    std::swap(swapped.ax, swapped.ay);
    Estimate e = mean_weight(Method::caps, params, 77);
    CAPTURE(e.mean);
    CAPTURE(ggxref::albedo(swapped));
    CHECK(std::fabs(e.mean - ggxref::albedo(swapped)) > 4.0 * e.standard_error);
}
