// test_chi_square_extremes.cpp - goodness of fit at the edges of each
// method's domain: alpha 1e-3 and 4, a view 89.9 degrees from
// the normal, anisotropy 1:100, and views below the horizon for the methods
// that sample them (heitz, caps, caps-iso, bounded; ndf does not look at the
// view).  1e6 samples per configuration, 24 x 48 bins, Sidak over the
// configurations of a method.
// At alpha 1e-3 every reflected direction lies within a few 1e-3 rad of the
// mirror direction, which no bin grid of the sphere resolves; those samples
// are tested in the standard configuration instead (Heitz 2018, sec. 2): the
// normals unstretched, m_std = normalize(mx / ax, my / ay, mz), follow the
// same method's distribution at alpha 1 for the stretched view.  (bounded's
// cap factor is then 1 - 1e-6: its standard-space normals are tested against
// the VNDF's.)
// Negative control: standard-space VNDF normals are rejected as NDF normals.
// Documented failure: a method whose traits say it takes no view below the
// horizon (heitz2017: its half disks assume iz >= 0; docs/STABILITY.md) is
// rejected there, and the test asserts that: the views_below trait of
// ggxcl::method_table is checked both ways.
#include <doctest/doctest.h>

#include <cmath>

#include "distribution_check.hpp"

namespace {

using ggxref::Method;

std::uint64_t next_seed()
{
    static std::uint64_t seed = 90000;
    return ++seed;
}

double fit_o(Method method, const ggxref::Params& params)
{
    return ggxtest::fit(ggxtest::device_histogram(method, params, next_seed()), method, params).p_value;
}

// Normals unstretched into the standard configuration, against the alpha-1 distribution there.
double fit_standard_space(Method method, const ggxref::Params& params, Method against)
{
    ggxcl::SampleSet s = ggxtest::device_samples(method, params, next_seed(), ggxtest::chi_square_samples,
                                                 {ggxcl::Field::m}, ggxcl::Precision::precise);
    std::vector<float> x(s.count), y(s.count), z(s.count);
    for (std::size_t j = 0; j < s.count; ++j) {
        double mx = s.m[j] / params.ax, my = s.m[s.count + j] / params.ay, mz = s.m[2 * s.count + j];
        double len = std::sqrt(mx * mx + my * my + mz * mz);
        x[j] = float(mx / len), y[j] = float(my / len), z[j] = float(mz / len);
    }
    ggxref::Params standard = params;
    standard.ax = standard.ay = 1.0;
    standard.i = ggxref::normalize({params.ax * params.i.x, params.ay * params.i.y, params.i.z});
    std::vector<double> expected = ggxref::bin_probabilities_m(against, standard, ggxtest::bins_z, ggxtest::bins_phi);
    std::vector<std::uint64_t> counts =
        ggxref::histogram_directions(x.data(), y.data(), z.data(), s.count, ggxtest::bins_z, ggxtest::bins_phi);
    return ggxref::chi_square_gof_float(counts, expected).p_value;
}

struct Extreme {
    ggxref::Params params;
    bool standard_space;
};

const ggxcl::MethodTraits& traits(Method method)
{
    return ggxcl::method_traits(ggxtest::to_library(method));
}

std::vector<Extreme> extremes(Method method)
{
    std::vector<Extreme> list = {{ggxtest::make_params(1e-3, 1e-3, 30.0), true},
                                 {ggxtest::make_params(1e-3, 1e-3, 89.95), true},  // stretched view at 49 degrees
                                 {ggxtest::make_params(4.0, 4.0, 0.0), false},
                                 {ggxtest::make_params(4.0, 4.0, 89.9), false},
                                 {ggxtest::make_params(0.3, 0.3, 89.9), false}};
    if (!traits(method).isotropic_only) {
        list.push_back({ggxtest::make_params(0.02, 2.0, 60.0), false});  // 1:100
        list.push_back({ggxtest::make_params(1.0, 0.01, 45.0), false});
    }
    if (traits(method).views_below) {
        list.push_back({ggxtest::make_params(0.5, 0.5, 120.0), false});
        list.push_back({ggxtest::make_params(1.0, 1.0, 150.0), false});
    }
    return list;
}

void check_extremes(Method method)
{
    std::vector<Extreme> list = extremes(method);
    double level = ggxref::sidak_level(ggxtest::family_level, int(list.size()));
    for (const Extreme& e : list) {
        // A density of its own (bounded): its standard-space normals against the VNDF's.
        Method against = traits(method).normals == ggxcl::Distribution::own ? Method::caps : method;
        double p = e.standard_space ? fit_standard_space(method, e.params, against) : fit_o(method, e.params);
        CAPTURE(ggxtest::describe(e.params));
        CAPTURE(e.standard_space);
        CHECK(p > level);
    }
}

} // namespace

TEST_CASE("extremes: ndf") { check_extremes(Method::ndf); }
TEST_CASE("extremes: heitz") { check_extremes(Method::heitz); }
TEST_CASE("extremes: heitz2017 above the horizon") { check_extremes(Method::heitz2017); }
TEST_CASE("extremes: caps") { check_extremes(Method::caps); }
TEST_CASE("extremes: caps-iso") { check_extremes(Method::caps_iso); }
TEST_CASE("extremes: bounded") { check_extremes(Method::bounded); }

TEST_CASE("documented failure: the methods without views_below (heitz2017) do not sample the VNDF below")
{
    ggxref::Params params = ggxtest::make_params(0.5, 0.5, 120.0);
    int failures = 0;
    for (Method method : ggxref::all_methods) {
        if (traits(method).views_below)
            continue;
        CAPTURE(ggxref::method_name(method));
        double p = ggxtest::fit(ggxtest::device_histogram(method, params, 4242), Method::heitz, params).p_value;
        CHECK(p < 1e-6);
        ++failures;
    }
    CHECK(failures == 1);  // heitz2017
}

TEST_CASE("negative control: in the standard configuration, VNDF normals are rejected as NDF normals")
{
    // (At alpha 1e-3 the stretched view of any view short of ~89.9 degrees is near the pole, where
    // the VNDF is the NDF's D(m) mz: the control takes the view at 89.95 degrees, 49 degrees stretched.)
    ggxref::Params params = ggxtest::make_params(1e-3, 1e-3, 89.95);
    CHECK(fit_standard_space(Method::caps, params, Method::ndf) < 1e-6);
}
