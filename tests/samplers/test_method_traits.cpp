// test_method_traits.cpp - each method's row of the table of traits
// (ggxcl::method_table, made from ggx_contract.h's GGX_METHOD_LIST) against
// what the method does on the device, so that a trait and the behaviour
// cannot disagree:
//   isotropic_only - (0.1, 0.6) is refused exactly for the methods marked so,
//                    and the others spread m wider along y than along x;
//   dielectric     - eta 1.5 is refused exactly for the methods without a
//                    dielectric sampler, and the others transmit (o below);
//   space          - a world-space method samples about the normal it is
//                    given; a tangent-space one ignores it (the same bits);
//   normals        - the returned pdf_o is the one of the distribution the
//                    row names (heitz's for the VNDF, ndf's for the NDF) and,
//                    for a density of its own, neither.
// Views below the horizon are test_chi_square_extremes' (chi-square at 120
// and 150 degrees for the methods marked views_below, rejection for the
// others).  The device functions of the traits (ggx_method_traits.h) are
// compared with the table too.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "device_fixture.hpp"
#include "ggx_method_traits.h"  // the device functions, compiled as C++ (kernels/ggx_platform.h)

namespace {

using ggxcl::Method;
using ggxcl::MethodTraits;

constexpr std::uint64_t samples = 1 << 14;

ggxcl::SampleParams params_of(Method method, float ax, float ay)
{
    ggxcl::SampleParams p;
    p.method = method;
    p.alpha_x = ax;
    p.alpha_y = ay;
    p.view = ggxcl::view_from_angles(50.0, 20.0);
    return p;
}

ggxcl::SampleSet draw(const ggxcl::SampleParams& p, ggxcl::FieldSet fields)
{
    return ggxtest::sampler().generate(ggxcl::normalized(p), {7, 0, samples}, fields);
}

double variance(const float* x, std::size_t n)
{
    double sum = 0.0, squares = 0.0;
    for (std::size_t j = 0; j < n; ++j)
        sum += x[j], squares += double(x[j]) * x[j];
    const double mean = sum / double(n);
    return squares / double(n) - mean * mean;
}

void check_isotropic_only(const MethodTraits& t)
{
    const ggxcl::SampleParams anisotropic = params_of(t.method, 0.1f, 0.6f);
    if (t.isotropic_only) {
        CHECK_THROWS_AS(ggxcl::normalized(anisotropic), ggxcl::InvalidArgument);
        return;
    }
    const ggxcl::SampleSet s = draw(anisotropic, {ggxcl::Field::m});
    const double var_x = variance(s.m.data(), s.count), var_y = variance(s.m.data() + s.count, s.count);
    CAPTURE(var_x);
    CAPTURE(var_y);
    CHECK(var_y > 4.0 * var_x);  // alpha_y six times alpha_x
}

void check_dielectric(const MethodTraits& t)
{
    ggxcl::SampleParams glass = params_of(t.method, 0.3f, 0.3f);
    glass.eta = 1.5f;
    if (!t.dielectric) {
        CHECK_THROWS_AS(ggxcl::normalized(glass), ggxcl::InvalidArgument);
        return;
    }
    const ggxcl::SampleSet s = draw(glass, {ggxcl::Field::o});
    std::uint64_t below = 0;
    for (std::size_t j = 0; j < s.count; ++j)
        below += s.o[2 * s.count + j] < 0.0f;
    CHECK(below > samples / 2);  // at 50 degrees glass transmits ~95%
}

// World space: the mean m follows the normal; tangent space: the normal changes no bit.
void check_space(const MethodTraits& t)
{
    ggxcl::SampleParams tilted = params_of(t.method, 0.2f, 0.2f);
    tilted.normal = {1.0f, 0.0f, 0.0f};
    tilted.view = {0.8f, 0.0f, 0.6f};  // above both +z and +x
    const ggxcl::SampleSet s = draw(tilted, {ggxcl::Field::m});
    double mean_x = 0.0, mean_z = 0.0;
    for (std::size_t j = 0; j < s.count; ++j)
        mean_x += s.m[j], mean_z += s.m[2 * s.count + j];
    mean_x /= double(s.count), mean_z /= double(s.count);
    CAPTURE(mean_x);
    CAPTURE(mean_z);
    if (t.space == ggxcl::Space::world) {
        CHECK(mean_x > 0.8);
        return;
    }
    CHECK(mean_z > 0.8);
    ggxcl::SampleParams upright = tilted;
    upright.normal = {0.0f, 0.0f, 1.0f};
    CHECK(draw(upright, {ggxcl::Field::m}).m == s.m);
}

// The relative difference of pdf_o and the pdf `of` gives the same directions, largest and median.
std::vector<double> pdf_differences(const ggxcl::SampleParams& p, const ggxcl::SampleSet& s, Method of)
{
    std::vector<ggxcl::Vec3> o(s.count);
    for (std::size_t j = 0; j < s.count; ++j)
        o[j] = {s.o[j], s.o[s.count + j], s.o[2 * s.count + j]};
    ggxcl::SampleParams q = p;
    q.method = of;
    const std::vector<float> pdf = ggxtest::sampler().pdf(ggxcl::normalized(q), o);
    std::vector<double> differences;
    for (std::size_t j = 0; j < s.count; ++j)
        if (s.pdf_o[j] > 0.0f)
            differences.push_back(std::fabs(pdf[j] / s.pdf_o[j] - 1.0));
    std::sort(differences.begin(), differences.end());
    return differences;
}

double median(const std::vector<double>& sorted)
{
    return sorted.empty() ? 1.0 : sorted[sorted.size() / 2];
}

void check_normals(const MethodTraits& t)
{
    const ggxcl::SampleParams p = params_of(t.method, 0.4f, 0.4f);
    const ggxcl::SampleSet s = draw(p, {ggxcl::Field::o, ggxcl::Field::pdf_o});
    const double vndf = median(pdf_differences(p, s, Method::heitz)), ndf = median(pdf_differences(p, s, Method::ndf));
    CAPTURE(vndf);
    CAPTURE(ndf);
    switch (t.normals) {
    case ggxcl::Distribution::vndf: CHECK(vndf < 1e-4); CHECK(ndf > 1e-2); break;
    case ggxcl::Distribution::ndf: CHECK(ndf < 1e-4); CHECK(vndf > 1e-2); break;
    case ggxcl::Distribution::own: CHECK(vndf > 1e-2); CHECK(ndf > 1e-2); break;
    }
}

} // namespace

TEST_CASE("every method's traits agree with what it does")
{
    for (const MethodTraits& t : ggxcl::method_table) {
        CAPTURE(t.name);
        CHECK(ggxcl::method_traits(t.method).name == t.name);
        CHECK(ggxcl::parse_method(t.name) == t.method);
        CHECK(t.limits.empty() == (t.dielectric && t.views_below && !t.isotropic_only));
        check_isotropic_only(t);
        check_dielectric(t);
        check_space(t);
        check_normals(t);
    }
}

TEST_CASE("the device headers' trait functions give the table's traits")
{
    for (const MethodTraits& t : ggxcl::method_table) {
        CAPTURE(t.name);
        const int id = int(t.method);
        CHECK(ggx_method_world_space(id) == (t.space == ggxcl::Space::world ? 1 : 0));
        CHECK(ggx_method_dielectric(id) == (t.dielectric ? 1 : 0));
        CHECK(ggx_method_ndf_normals(id) == (t.normals == ggxcl::Distribution::ndf ? 1 : 0));
    }
    CHECK(ggx_method_dielectric(GGX_METHOD_USER) == 0);  // a user sampler: no trait
}

TEST_CASE("the traits' checks fail on a wrong trait (negative control)")
{
    // Each check run on a row with one trait flipped must fail: run on caps, marked the opposite way.
    MethodTraits wrong = ggxcl::method_traits(Method::caps);
    wrong.normals = ggxcl::Distribution::ndf;
    const ggxcl::SampleParams p = params_of(Method::caps, 0.4f, 0.4f);
    const ggxcl::SampleSet s = draw(p, {ggxcl::Field::o, ggxcl::Field::pdf_o});
    CHECK(median(pdf_differences(p, s, Method::ndf)) > 1e-2);  // what check_normals asserts < 1e-4 for ndf
    ggxcl::SampleParams tilted = params_of(Method::caps_iso, 0.2f, 0.2f);
    tilted.normal = {1.0f, 0.0f, 0.0f};
    tilted.view = {0.8f, 0.0f, 0.6f};
    const ggxcl::SampleSet world = draw(tilted, {ggxcl::Field::m});
    double mean_z = 0.0;
    for (std::size_t j = 0; j < world.count; ++j)
        mean_z += world.m[2 * world.count + j];
    CHECK(mean_z / double(world.count) < 0.8);  // caps-iso as if tangent space fails check_space
    CHECK_NOTHROW(ggxcl::normalized(params_of(Method::caps, 0.1f, 0.6f)));  // an isotropic_only caps would fail
}
