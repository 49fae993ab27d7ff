// test_stress.cpp - the stability map (`ggx stress`) and the guards:
//  - the classification of one outcome by failure kind, on hand-made outcomes;
//  - no NaN or Inf anywhere on the stress grid, every method, device (in
//    each precision mode), host reference and the device headers compiled
//    as C++;
//  - the fallback (docs/STABILITY.md) happens exactly where documented: a
//    roughness axis of 0, the view exactly opposite the normal (the VNDF
//    family), caps-iso at n = (0, 0, -1); never inside the domain;
//  - the tool's CSV (one row per method, side and cell; every case counted),
//    bad input, and the precision modes it offers (the library's, no more).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "cli_runner.hpp"
#include "stress_dielectric.hpp"
#include "stress_run.hpp"

#include <ggxcl/ggxcl.hpp>

namespace {

using ggxapp::StressOutcome;

// A good sample: m and o unit above the surface, positive consistent pdfs.
StressOutcome good()
{
    double s = std::sqrt(0.5);
    return {{0.0, 0.0, 1.0}, {s, 0.0, s}, 2.0, 0.5, 0.9, 0.5};
}

std::vector<std::string> kinds_of(const StressOutcome& outcome)
{
    std::vector<std::string> names;
    std::array<bool, ggxapp::failure_kinds> kinds = ggxapp::classify(outcome, {0.0f, 0.0f, 1.0f});
    for (int k = 0; k < ggxapp::failure_kinds; ++k)
        if (kinds[k])
            names.push_back(ggxapp::failure_name(k));
    return names;
}

using Names = std::vector<std::string>;

ggxcl::Sampler& sampler()
{
    static ggxcl::Sampler instance;
    return instance;
}

// Totals of one kind (-1: the cases) over a map, the conductor's or the dielectric's.
template <class Map> std::uint64_t total(const Map& map, int kind)
{
    std::uint64_t n = 0;
    for (const auto& cell : map)
        n += kind < 0 ? cell.cases : cell.failures[kind];
    return n;
}

// The cases of `all` that `keep` selects.
template <class Keep> std::vector<ggxapp::StressCase> kept_cases(std::vector<ggxapp::StressCase> all, Keep keep)
{
    all.erase(std::remove_if(all.begin(), all.end(), [&](const ggxapp::StressCase& c) { return !keep(c); }),
              all.end());
    return all;
}

// The cases of the full grid that `keep` selects.
template <class Keep>
std::vector<ggxapp::StressCase> cases_where(ggxcl::Method method, const ggxapp::StressAxes& axes, Keep keep)
{
    return kept_cases(ggxapp::stress_cases(method, axes), keep);
}

bool is_vndf(ggxcl::Method method)
{
    return method != ggxcl::Method::ndf;
}

// Device (precise mode), host reference and C++ (the device headers compiled by the host
// compiler) maps of `cases`.
struct BothSides {
    ggxapp::StressMap device, host, cpp;
};

BothSides both_sides(ggxcl::Method method, const std::vector<ggxapp::StressCase>& cases,
                     const ggxapp::StressAxes& axes)
{
    const std::vector<StressOutcome> reference = ggxapp::host_outcomes(method, cases);  // drawn once for the three
    return {ggxapp::map_against(ggxapp::device_outcomes(sampler(), method, ggxcl::Precision::precise, cases), reference,
                                cases, axes),
            ggxapp::map_against(reference, reference, cases, axes),
            ggxapp::map_against(ggxapp::cpp_outcomes(method, cases), reference, cases, axes)};
}

} // namespace

TEST_CASE("classify names each failure kind and nothing else")
{
    CHECK(kinds_of(good()).empty());
    StressOutcome s = good();
    s.pdf_o = std::numeric_limits<double>::quiet_NaN();
    CHECK(kinds_of(s) == Names{"nan_inf"});
    s = good();
    s.weight = std::numeric_limits<double>::infinity();
    CHECK(kinds_of(s) == Names{"nan_inf"});
    s = good();
    s.m[0] = s.m[1] = 0.0, s.m[2] = 1.0, s.pdf_m = s.pdf_o = s.weight = 0.0;
    CHECK(kinds_of(s) == Names{"fallback"});
    s = good();
    s.m[2] = 1.001;
    CHECK(kinds_of(s) == Names{"not_unit"});
    s = good();
    s.m[2] = -1.0;
    CHECK(kinds_of(s) == Names{"m_below"});
    s = good();
    s.o[2] = -s.o[2];
    CHECK(kinds_of(s) == Names{"wasted"});  // a wasted sample's pdf is not judged
    s.pdf_m = -1e-3;
    CHECK(kinds_of(s) == (Names{"wasted", "pdf_nonpositive"}));  // unless it is negative
    s = good();
    s.pdf_o = s.pdf_again = 0.0;
    CHECK(kinds_of(s) == Names{"pdf_nonpositive"});
    s = good();
    s.pdf_again = 0.5 * (1 + 2e-3);
    CHECK(kinds_of(s) == Names{"pdf_mismatch"});
    s.pdf_again = 0.5 * (1 + 5e-4);
    CHECK(kinds_of(s).empty());
}

TEST_CASE("a sample off the reference's by more than its uniforms' bound counts as inaccurate, by kind")
{
    const ggxapp::StressAxes axes = ggxapp::stress_axes();
    ggxapp::StressCase random_case{0.3f, 0.3f, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f}, 0.1f, 0.2f, 0, 0};
    random_case.random = true;
    ggxapp::StressCase edge_case = random_case;
    edge_case.random = false;
    const std::vector<ggxapp::StressCase> cases = {random_case, edge_case};
    const StressOutcome reference = good();
    // m and o turned about y by `angle`.
    auto turned = [&](double angle) {
        StressOutcome s = reference;
        for (double* v : {s.m, s.o}) {
            const double x = v[0], z = v[2];
            v[0] = std::cos(angle) * x + std::sin(angle) * z;
            v[2] = -std::sin(angle) * x + std::cos(angle) * z;
        }
        return s;
    };
    auto counts = [&](double angle) {  // inaccurate, inaccurate_edge in the cases' cell
        const ggxapp::StressMap map = ggxapp::map_against({turned(angle), turned(angle)}, {reference, reference},
                                                          cases, axes);
        return std::pair{map[0].failures[ggxapp::inaccurate], map[0].failures[ggxapp::inaccurate_edge]};
    };
    CHECK(counts(1e-6) == std::pair<std::uint64_t, std::uint64_t>{0, 0});
    CHECK(counts(1e-4) == std::pair<std::uint64_t, std::uint64_t>{1, 0});
    CHECK(counts(1e-2) == std::pair<std::uint64_t, std::uint64_t>{1, 1});
    StressOutcome fallback = reference;  // the fallback is not judged
    fallback.m[0] = fallback.m[1] = 0.0, fallback.m[2] = 1.0, fallback.pdf_m = fallback.pdf_o = fallback.weight = 0.0;
    const ggxapp::StressMap map = ggxapp::map_against({fallback, fallback}, {reference, reference}, cases, axes);
    CHECK(map[0].failures[ggxapp::inaccurate] + map[0].failures[ggxapp::inaccurate_edge] == 0);
}

TEST_CASE("ggx stress writes one row per method, side and cell, with every case counted")
{
    ggxtest::fs::path dir = ggxtest::scratch_dir("stress");
    ggxtest::Run run =
        ggxtest::run_ggx("stress --methods caps,caps-iso --no-png --out " + (dir / "map").string(), dir / "err.txt");
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    std::stringstream csv(ggxtest::read_all(dir / "map.csv"));
    std::string line;
    std::getline(csv, line);
    CHECK(line == "method,side,precision,alpha,theta_degrees,cases,nan_inf,fallback,not_unit,m_below,wasted,"
                  "pdf_nonpositive,pdf_mismatch,inaccurate,inaccurate_edge");
    int rows = 0;
    while (std::getline(csv, line)) {
        std::stringstream fields(line);
        std::vector<std::string> f;
        std::string field;
        while (std::getline(fields, field, ','))
            f.push_back(field);
        REQUIRE(f.size() == 15);
        CAPTURE(line);
        long cases = std::stol(f[5]);
        CHECK(cases == 90);  // caps: 5 roughness pairs x 18 uniform pairs; caps-iso: 5 normals x 18
        for (int k = 6; k < 15; ++k)
            CHECK(std::stol(f[k]) <= cases);
        CHECK(f[6] == "0");  // no NaN or Inf anywhere
        ++rows;
    }
    CHECK(rows == 2 * 2 * 19 * 18);  // 2 methods x (device, host) x 19 alphas x 18 views
    ggxtest::fs::remove_all(dir);
}

TEST_CASE("ggx stress: bad input exits 2 naming the flag")
{
    ggxtest::fs::path dir = ggxtest::scratch_dir("stress-bad");
    struct Case {
        std::string args, flag;
    } cases[] = {
        {"stress --methods walter --out " + (dir / "m").string(), "--methods"},
        {"stress --methods caps, --out " + (dir / "m").string(), "--methods"},
        {"stress --precision turbo --out " + (dir / "m").string(), "--precision"},
        {"stress --out /dev/null/no-folder/m", "--out"},
    };
    for (const Case& c : cases) {
        ggxtest::Run run = ggxtest::run_ggx(c.args, dir / "err.txt");
        CAPTURE(c.args);
        CAPTURE(run.err);
        CHECK(run.status == 2);
        CHECK(run.err.find(c.flag) != std::string::npos);
    }
    ggxtest::fs::remove_all(dir);
}

TEST_CASE("ggx stress offers and accepts exactly the library's precision modes")
{
    ggxtest::fs::path dir = ggxtest::scratch_dir("stress-precision");
    const std::string allowed = "allowed is one of " + ggxcl::precision_list();
    ggxtest::Run fast =
        ggxtest::run_ggx("stress --precision fast --no-png --out " + (dir / "m").string(), dir / "err.txt");
    CAPTURE(fast.err);
    CHECK(fast.status == 2);
    CHECK(fast.err.find("--precision: invalid value 'fast': " + allowed) != std::string::npos);
    CHECK(fast.err.find("fast", fast.err.find("allowed is")) == std::string::npos);  // not among the allowed
    // The help (on stdout, sent to the captured stderr here).
    ggxtest::Run help =
        ggxtest::run_ggx("{ " + ggxtest::ggx_binary() + " stress --help 1>&2; }", dir / "help.txt", false);
    CAPTURE(help.err);
    CHECK(help.status == 0);
    const std::size_t line = help.err.find("--precision");
    REQUIRE(line != std::string::npos);
    const std::string precision_help = help.err.substr(line, help.err.find('\n', line) - line);
    for (ggxcl::Precision precision : ggxcl::all_precisions)
        CHECK(precision_help.find(ggxcl::precision_name(precision)) != std::string::npos);
    CHECK(help.err.find("fast") == std::string::npos);
    ggxtest::fs::remove_all(dir);
}

TEST_CASE("no NaN or Inf anywhere on the stress grid: every method, device in every mode, host, C++")
{
    ggxapp::StressAxes axes = ggxapp::stress_axes();
    for (ggxcl::Method method : ggxcl::all_methods) {
        std::vector<ggxapp::StressCase> cases = ggxapp::stress_cases(method, axes);
        CAPTURE(ggxcl::method_name(method));
        const std::vector<StressOutcome> reference = ggxapp::host_outcomes(method, cases);  // drawn once
        for (ggxcl::Precision precision : ggxcl::all_precisions) {
            CAPTURE(ggxcl::precision_name(precision));
            const std::vector<StressOutcome> device = ggxapp::device_outcomes(sampler(), method, precision, cases);
            CHECK(total(ggxapp::map_against(device, reference, cases, axes), ggxapp::nan_inf) == 0);
        }
        CHECK(total(ggxapp::map_against(reference, reference, cases, axes), ggxapp::nan_inf) == 0);
        const std::vector<StressOutcome> cpp = ggxapp::cpp_outcomes(method, cases);
        CHECK(total(ggxapp::map_against(cpp, reference, cases, axes), ggxapp::nan_inf) == 0);
    }
}

TEST_CASE("negative control: without the guards the same grid has NaN and Inf")
{
    ggxapp::StressAxes axes = ggxapp::stress_axes();
    for (ggxcl::Method method : {ggxcl::Method::caps, ggxcl::Method::caps_iso}) {
        std::vector<ggxapp::StressCase> cases = ggxapp::stress_cases(method, axes);
        CAPTURE(ggxcl::method_name(method));
        CHECK(total(ggxapp::device_stress_map(sampler(), method, ggxcl::Precision::precise, cases, axes, false),
                    ggxapp::nan_inf) > 1000);
    }
}

TEST_CASE("the fallback happens where documented: a roughness axis of 0")
{
    ggxapp::StressAxes axes = ggxapp::stress_axes();
    for (ggxcl::Method method : ggxcl::all_methods) {
        if (method == ggxcl::Method::caps_iso)
            continue;  // isotropic: its grid has no zero axis (the runtime refuses alpha 0 anyway)
        auto cases = cases_where(method, axes, [](const ggxapp::StressCase& c) { return c.ax == 0.0f || c.ay == 0.0f; });
        BothSides maps = both_sides(method, cases, axes);
        CAPTURE(ggxcl::method_name(method));
        CHECK(total(maps.device, ggxapp::fallback) == cases.size());
        CHECK(total(maps.host, ggxapp::fallback) == cases.size());
        CHECK(total(maps.cpp, ggxapp::fallback) == cases.size());
    }
}

TEST_CASE("the fallback happens where documented: the view exactly opposite the normal, caps-iso at n = -z")
{
    ggxapp::StressAxes axes = ggxapp::stress_axes();
    for (ggxcl::Method method : ggxcl::all_methods) {
        auto opposite = cases_where(method, axes, [](const ggxapp::StressCase& c) {
            return c.ax > 0.0f && c.ay > 0.0f && c.normal.z == 1.0f && c.view.z == -1.0f;
        });
        BothSides maps = both_sides(method, opposite, axes);
        CAPTURE(ggxcl::method_name(method));
        REQUIRE(!opposite.empty());
        std::uint64_t expected = is_vndf(method) ? opposite.size() : 0;  // ndf samples normals, not visible ones
        CHECK(total(maps.device, ggxapp::fallback) == expected);
        CHECK(total(maps.host, ggxapp::fallback) == expected);
        CHECK(total(maps.cpp, ggxapp::fallback) == expected);
    }
    auto pole = cases_where(ggxcl::Method::caps_iso, axes,
                            [](const ggxapp::StressCase& c) { return c.normal.z == -1.0f; });
    BothSides maps = both_sides(ggxcl::Method::caps_iso, pole, axes);
    CHECK(total(maps.device, ggxapp::fallback) == pole.size());
    CHECK(total(maps.host, ggxapp::fallback) == pole.size());
    CHECK(total(maps.cpp, ggxapp::fallback) == pole.size());
}

TEST_CASE("inside the domain nothing fails: alpha 1e-2..1e2 (anisotropy to 1:1000 within it), views to 89 degrees")
{
    ggxapp::StressAxes axes = ggxapp::stress_axes();
    const double cos_89 = std::cos(89.0 * 3.14159265358979323846 / 180.0);
    for (ggxcl::Method method : ggxcl::all_methods) {
        auto inside = cases_where(method, axes, [&](const ggxapp::StressCase& c) {
            return std::min(c.ax, c.ay) >= 1e-2f && axes.cos_theta[c.column] >= cos_89 - 1e-12 && c.normal.z > -0.99f;
        });
        BothSides maps = both_sides(method, inside, axes);
        CAPTURE(ggxcl::method_name(method));
        REQUIRE(!inside.empty());
        for (int kind = 0; kind < ggxapp::failure_kinds; ++kind) {
            if (kind == ggxapp::wasted || kind == ggxapp::inaccurate_edge)
                continue;  // not a failure; reported apart (the edge uniforms: 1 - 2^-24 rounds at sqrt and
                           // at the cap's rim, where m is ill-conditioned in float: docs/STABILITY.md)
            CAPTURE(ggxapp::failure_name(kind));
            CHECK(total(maps.host, kind) == 0);
            // caps-iso's general form (any n; the runtime uses the exact tangent-space form for
            // n = +z): m.n of a microfacet at the cap's edge is 0 only to within the rounding of
            // world-space vectors (docs/STABILITY.md).
            if (method == ggxcl::Method::caps_iso && kind == ggxapp::m_below)
                continue;
            CHECK(total(maps.device, kind) == 0);
            CHECK(total(maps.cpp, kind) == 0);
        }
    }
}

TEST_CASE("views from below to 179.9 degrees: heitz, caps, bounded and caps-iso about +z stay within 2e-5 rad of the "
          "reference on random uniforms at every roughness of the map")
{
    const ggxapp::StressAxes axes = ggxapp::stress_axes();
    for (ggxcl::Method method : {ggxcl::Method::heitz, ggxcl::Method::caps, ggxcl::Method::bounded, ggxcl::Method::caps_iso}) {
        CAPTURE(ggxcl::method_name(method));
        const auto below = cases_where(method, axes, [&](const ggxapp::StressCase& c) {
            return axes.cos_theta[c.column] < 0.0 && c.normal.z == 1.0f;  // about +z: float world space aside
        });
        REQUIRE(!below.empty());
        const BothSides maps = both_sides(method, below, axes);
        CHECK(total(maps.device, ggxapp::inaccurate) == 0);
        CHECK(total(maps.cpp, ggxapp::inaccurate) == 0);
    }
    // Negative control: heitz2017 keeps the cancelling 1 + vz there (its half disks assume iz >= 0).
    const auto below = cases_where(ggxcl::Method::heitz2017, axes,
                                   [&](const ggxapp::StressCase& c) { return axes.cos_theta[c.column] < 0.0; });
    CHECK(total(ggxapp::device_stress_map(sampler(), ggxcl::Method::heitz2017, ggxcl::Precision::precise, below, axes),
                ggxapp::inaccurate) > 0);
}

// ---- The rough dielectric's map (`ggx stress --eta`, stress_dielectric.hpp) ----

namespace {

namespace dl = ggxapp::dielectric;

std::vector<ggxcl::Method> dielectric_methods()
{
    std::vector<ggxcl::Method> methods;
    for (ggxcl::Method method : ggxcl::all_methods)
        if (method != ggxcl::Method::bounded)
            methods.push_back(method);
    return methods;
}

ggxapp::StressAxes dielectric_grid() { return ggxapp::dielectric_axes(ggxapp::dielectric_etas()); }

// The cases of the dielectric grid that `keep` selects.
template <class Keep>
std::vector<ggxapp::StressCase> dielectric_cases_where(ggxcl::Method method, const ggxapp::StressAxes& axes, Keep keep)
{
    return kept_cases(ggxapp::dielectric_cases(method, axes), keep);
}

struct DielectricSides {
    dl::Map device, host, cpp;
};

DielectricSides dielectric_sides(ggxcl::Method method, const std::vector<ggxapp::StressCase>& cases,
                                 const ggxapp::StressAxes& axes)
{
    return {dl::device_map(sampler(), method, ggxcl::Precision::precise, cases, axes),
            dl::host_map(method, cases, axes), dl::cpp_map(method, cases, axes)};
}

// A view 60 degrees from the normal at azimuth 0, eta 1.5, and a valid transmission of it through
// m = n: o = -(sin t, 0, cos t) with Snell's law, unit, pdfs positive and consistent.
ggxapp::StressCase refraction_case()
{
    const double s = std::sqrt(0.75);
    return {0.3f, 0.3f, {float(s), 0.0f, 0.5f}, {0.0f, 0.0f, 1.0f}, 0.5f, 0.5f, 0, 0, 0.9f, 1.5f};
}

StressOutcome refraction()
{
    const double sin_t = std::sqrt(0.75) / 1.5, cos_t = std::sqrt(1.0 - sin_t * sin_t);
    return {{0.0, 0.0, 1.0}, {-sin_t, 0.0, -cos_t}, 2.0, 0.5, 0.8 / 2.25, 0.5, 0.8};
}

std::vector<std::string> dielectric_kinds_of(const StressOutcome& outcome, const ggxapp::StressCase& c)
{
    std::vector<std::string> names;
    std::array<bool, dl::kinds> kinds = dl::classify(outcome, c);
    for (int k = 0; k < dl::kinds; ++k)
        if (kinds[k])
            names.push_back(dl::kind_name(k));
    return names;
}

// A view within 89 degrees of either pole.
bool off_grazing(const ggxapp::StressAxes& axes, const ggxapp::StressCase& c)
{
    return std::fabs(axes.cos_theta[c.column]) >= std::cos(89.0 * 3.14159265358979323846 / 180.0) - 1e-12;
}

// A uniform at 1 - 2^-24: the edge of the disk or cap, microfacets seen edge-on.
bool rim_uniform(const ggxapp::StressCase& c)
{
    const float one_below = 1.0f - 5.9604644775390625e-8f;
    return c.u1 == one_below || c.u2 == one_below;
}

} // namespace

TEST_CASE("dielectric classify names each kind and nothing else (planted failures)")
{
    const ggxapp::StressCase c = refraction_case();
    CHECK(dielectric_kinds_of(refraction(), c) == Names{"transmitted"});
    StressOutcome s = refraction();
    s.pdf_again = std::numeric_limits<double>::infinity();
    CHECK(dielectric_kinds_of(s, c) == Names{"nan_inf"});
    s = refraction();
    s.o[0] = s.o[1] = 0.0, s.o[2] = 1.0, s.pdf_m = s.pdf_o = s.weight = s.weight_importance = 0.0;
    CHECK(dielectric_kinds_of(s, c) == Names{"fallback"});
    s.m[2] = s.o[2] = -1.0;  // the fallback is on the view's side
    CHECK(dielectric_kinds_of(s, c) == (Names{"m_side", "invalid"}));
    s = refraction();
    s.o[2] *= 1.001;
    CHECK(dielectric_kinds_of(s, c) == (Names{"not_unit", "transmitted"}));
    s = refraction();
    s.pdf_o = s.weight = s.weight_importance = 0.0;
    CHECK(dielectric_kinds_of(s, c) == Names{"invalid"});
    s.weight_importance = 0.1;  // a weight without density
    CHECK(dielectric_kinds_of(s, c) == (Names{"invalid", "bad_weight"}));
    s = refraction();
    s.weight = s.weight_importance;  // radiance transport not divided by eta^2
    CHECK(dielectric_kinds_of(s, c) == (Names{"transmitted", "bad_weight"}));
    ggxapp::StressCase other_side = c;
    other_side.eta = 1.0f / 1.5f;  // the other side's index: Snell's law and the weights disagree
    CHECK(dielectric_kinds_of(refraction(), other_side) == (Names{"transmitted", "bad_weight", "off_lobe"}));
    s = refraction();
    s.pdf_m = 0.0;
    CHECK(dielectric_kinds_of(s, c) == (Names{"transmitted", "pdf_nonpositive"}));
    s = refraction();
    s.pdf_again = 0.5 * (1 + 2e-3);
    CHECK(dielectric_kinds_of(s, c) == (Names{"transmitted", "pdf_mismatch"}));
    s.pdf_again = 0.5 * (1 + 5e-4);
    CHECK(dielectric_kinds_of(s, c) == Names{"transmitted"});
}

TEST_CASE("ggx stress --eta writes one row per method, side, index and cell; bounded is refused")
{
    ggxtest::fs::path dir = ggxtest::scratch_dir("stress-eta");
    const std::string prefix = (dir / "map").string();
    ggxtest::Run run = ggxtest::run_ggx(
        "{ " + ggxtest::ggx_binary() + " stress --eta 1.5,0.9999 --methods caps,bounded --no-png --out " + prefix +
            " 1>&2; }",
        dir / "out.txt", false);
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    CHECK(run.err.find("| bounded | refused: " + std::string(ggxcl::method_traits(ggxcl::Method::bounded).limits) +
                       " |") != std::string::npos);
    CHECK(run.err.find("| 1.5 | device | ") != std::string::npos);  // the totals per index
    std::stringstream csv(ggxtest::read_all(dir / "map.csv"));
    std::string line;
    std::getline(csv, line);
    CHECK(line == "method,side,precision,eta,alpha,theta_degrees,cases,nan_inf,fallback,not_unit,m_side,invalid,"
                  "transmitted,bad_weight,off_lobe,pdf_nonpositive,pdf_mismatch");
    int rows = 0;
    while (std::getline(csv, line)) {
        CAPTURE(line);
        std::stringstream fields(line);
        std::vector<std::string> f;
        for (std::string field; std::getline(fields, field, ',');)
            f.push_back(field);
        REQUIRE(f.size() == 17);
        CHECK(f[0] == "caps");
        CHECK((f[3] == "1.5" || f[3] == "0.999899983"));
        CHECK(std::stol(f[6]) == 270);  // 5 roughness pairs x 54 uniform triples
        CHECK(f[7] == "0");             // no NaN or Inf
        ++rows;
    }
    CHECK(rows == 2 * 2 * 19 * 18);  // (device, host) x 2 indices x 19 alphas x 18 views
}

TEST_CASE("ggx stress: a bad --eta exits 2 naming the flag and the allowed range")
{
    ggxtest::fs::path dir = ggxtest::scratch_dir("stress-eta-bad");
    for (std::string eta : {"1", "-1", "nan", "x", "0", "inf", "1.5,", "1.5,,2", "1.00000001"}) {
        ggxtest::Run run = ggxtest::run_ggx("stress --eta '" + eta + "' --no-png --out " + (dir / "m").string(),
                                            dir / "err.txt");
        CAPTURE(eta);
        CAPTURE(run.err);
        CHECK(run.status == 2);
        CHECK(run.err.find("--eta: invalid value '" + eta + "'") != std::string::npos);
        CHECK(run.err.find("> 0 and != 1") != std::string::npos);
    }
}

TEST_CASE("ggx stress without --eta is the conductor's map, as before")
{
    ggxtest::fs::path dir = ggxtest::scratch_dir("stress-default");
    ggxtest::Run run = ggxtest::run_ggx("{ " + ggxtest::ggx_binary() + " stress --methods caps --no-png --out " +
                                            (dir / "map").string() + " 1>&2; }",
                                        dir / "out.txt", false);
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    // The totals table exactly (the host's row is the double reference's: docs/STABILITY.md).
    const std::string header = "| method | side | cases | nan_inf | fallback | not_unit | m_below | wasted | "
                               "pdf_nonpositive | pdf_mismatch | inaccurate | inaccurate_edge |\n"
                               "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    CHECK(run.err.rfind(header, 0) == 0);
    CHECK(run.err.find("| caps | host | 30780 | 0 | 13356 | 0 | 0 | 1543 | 0 | 185 | 0 | 0 |\n") != std::string::npos);
    CHECK(run.err.find("eta") == std::string::npos);
    std::string first_line = ggxtest::read_all(dir / "map.csv").substr(0, 40);
    CHECK(first_line.rfind("method,side,precision,alpha,", 0) == 0);
}

TEST_CASE("no NaN or Inf anywhere on the dielectric grid: every method, device in every mode, host, C++")
{
    ggxapp::StressAxes axes = dielectric_grid();
    for (ggxcl::Method method : dielectric_methods()) {
        std::vector<ggxapp::StressCase> cases = ggxapp::dielectric_cases(method, axes);
        CAPTURE(ggxcl::method_name(method));
        for (ggxcl::Precision precision : ggxcl::all_precisions) {
            CAPTURE(ggxcl::precision_name(precision));
            CHECK(total(dl::device_map(sampler(), method, precision, cases, axes), dl::nan_inf) == 0);
        }
        CHECK(total(dl::host_map(method, cases, axes), dl::nan_inf) == 0);
        CHECK(total(dl::cpp_map(method, cases, axes), dl::nan_inf) == 0);
    }
}

TEST_CASE("negative control: without the guards the dielectric grid has NaN and Inf")
{
    ggxapp::StressAxes axes = ggxapp::dielectric_axes({1.5f});
    for (ggxcl::Method method : {ggxcl::Method::caps, ggxcl::Method::caps_iso}) {
        std::vector<ggxapp::StressCase> cases = ggxapp::dielectric_cases(method, axes);
        CAPTURE(ggxcl::method_name(method));
        CHECK(total(dl::device_map(sampler(), method, ggxcl::Precision::precise, cases, axes, false), dl::nan_inf) >
              1000);
    }
}

TEST_CASE("negative control: the device's samples judged with the other side's index fail the lobe and weight checks")
{
    ggxapp::StressAxes axes = ggxapp::dielectric_axes({1.5f});
    auto cases = dielectric_cases_where(ggxcl::Method::heitz, axes, [&](const ggxapp::StressCase& c) {
        return c.ax >= 1e-2f && c.ay >= 1e-2f && !rim_uniform(c) && off_grazing(axes, c);
    });
    std::vector<StressOutcome> outcomes =
        dl::device_outcomes(sampler(), ggxcl::Method::heitz, ggxcl::Precision::precise, cases);
    std::uint64_t right = 0, wrong = 0, transmitted = 0;
    for (std::size_t j = 0; j < cases.size(); ++j) {
        ggxapp::StressCase other = cases[j];
        other.eta = 1.0f / 1.5f;
        right += dl::classify(outcomes[j], cases[j])[dl::off_lobe];
        transmitted += dl::classify(outcomes[j], cases[j])[dl::transmitted];
        std::array<bool, dl::kinds> kinds = dl::classify(outcomes[j], other);
        wrong += kinds[dl::off_lobe] || kinds[dl::bad_weight];
    }
    CHECK(right == 0);
    CHECK(transmitted > 1000);
    CHECK(wrong == transmitted);  // every transmission
}

TEST_CASE("the dielectric's fallback happens where documented: a roughness axis of 0, caps-iso at n = -z")
{
    ggxapp::StressAxes axes = dielectric_grid();
    for (ggxcl::Method method : dielectric_methods()) {
        CAPTURE(ggxcl::method_name(method));
        auto documented = [](const ggxapp::StressCase& c) { return c.ax == 0.0f || c.ay == 0.0f || c.normal.z == -1.0f; };
        auto there = dielectric_cases_where(method, axes, documented);
        DielectricSides maps = dielectric_sides(method, there, axes);
        REQUIRE(!there.empty());
        CHECK(total(maps.device, dl::fallback) == there.size());
        CHECK(total(maps.host, dl::fallback) == there.size());
        CHECK(total(maps.cpp, dl::fallback) == there.size());
        // Nowhere else, but for caps-iso in float (device and C++): the view exactly at -n about a tilted
        // normal, mirrored to within rounding of n, with the cap point at -v (u2 = 1 - 2^-24): h = c + v vanishes.
        auto rest = dielectric_cases_where(method, axes, [&](const ggxapp::StressCase& c) { return !documented(c); });
        CHECK(total(dl::host_map(method, rest, axes), dl::fallback) == 0);
        auto float_rest = dielectric_cases_where(method, axes, [&](const ggxapp::StressCase& c) {
            const bool rounding = method == ggxcl::Method::caps_iso && c.column == int(axes.cos_theta.size()) - 1 &&
                                  c.normal.z != 1.0f && rim_uniform(c);
            return !documented(c) && !rounding;
        });
        CHECK(total(dl::device_map(sampler(), method, ggxcl::Precision::precise, float_rest, axes), dl::fallback) ==
              0);
        CHECK(total(dl::cpp_map(method, float_rest, axes), dl::fallback) == 0);
    }
}

// The failures of each kind among `outcomes`, leaving out the transmissions that graze their
// microfacet (|o.m| < 1e-2: within a hair of the critical angle, where 1 - F and the Jacobian vanish
// like the square root of a difference that float cancels).
struct OffCritical {
    std::array<std::uint64_t, dl::kinds> failures{};
    std::uint64_t left_out = 0;
};

OffCritical failures_off_critical(const std::vector<StressOutcome>& outcomes,
                                  const std::vector<ggxapp::StressCase>& cases)
{
    OffCritical counts;
    for (std::size_t j = 0; j < cases.size(); ++j) {
        const StressOutcome& s = outcomes[j];
        std::array<bool, dl::kinds> kinds = dl::classify(s, cases[j]);
        const double om = s.o[0] * s.m[0] + s.o[1] * s.m[1] + s.o[2] * s.m[2];
        if (kinds[dl::transmitted] && std::fabs(om) < 1e-2) {
            ++counts.left_out;
            continue;
        }
        for (int k = 0; k < dl::kinds; ++k)
            counts.failures[k] += dl::is_failure(k) && kinds[k];
    }
    return counts;
}

TEST_CASE("inside the dielectric's domain nothing fails: typical indices, alpha 1e-2..1e2, views to 89 degrees from "
          "either side")
{
    ggxapp::StressAxes axes = ggxapp::dielectric_axes({1.0f / 1.5f, 1.33f, 1.5f, 2.4f});
    for (ggxcl::Method method : dielectric_methods()) {
        auto inside = dielectric_cases_where(method, axes, [&](const ggxapp::StressCase& c) {
            const float low = std::min(c.ax, c.ay);
            const bool anisotropic = c.ax != c.ay;  // 1:1000 with the small axis below 0.1: docs/STABILITY.md
            return low >= 1e-2f && (!anisotropic || low >= 0.1f) && off_grazing(axes, c) && !rim_uniform(c) &&
                   c.normal.z > -0.99f;
        });
        CAPTURE(ggxcl::method_name(method));
        REQUIRE(!inside.empty());
        const std::vector<StressOutcome> sides[] = {
            dl::device_outcomes(sampler(), method, ggxcl::Precision::precise, inside),
            dl::host_outcomes(method, inside), dl::cpp_outcomes(method, inside)};
        for (const char* side : {"device", "host", "C++"}) {
            CAPTURE(side);
            const int k = side[0] == 'd' ? 0 : side[0] == 'h' ? 1 : 2;
            OffCritical counts = failures_off_critical(sides[k], inside);
            CHECK(counts.left_out * 200 < inside.size());  // under 0.5%
            for (int kind = 0; kind < dl::kinds; ++kind) {
                CAPTURE(std::string(dl::kind_name(kind)));
                CHECK(counts.failures[kind] == 0);
            }
        }
    }
}

TEST_CASE("total internal reflection: no transmission beyond the critical angle, all within it (alpha <= 1e-3)")
{
    // Columns of dielectric_axes: 0, 30, 45, 60, 85, 89 degrees, ... 120 (13), 135, 150, 179, 180 (17).
    ggxapp::StressAxes axes = ggxapp::dielectric_axes({1.5f, 1.0f / 1.5f});
    auto beyond = [](const ggxapp::StressCase& c) {  // views in the glass 45 degrees or more from its pole
        return c.eta == 1.5f ? (c.column == 13 || c.column == 14) : (c.column >= 2 && c.column <= 5);
    };
    auto within = [](const ggxapp::StressCase& c) {  // 30 degrees or less
        return c.eta == 1.5f ? c.column >= 15 : c.column <= 1;
    };
    for (ggxcl::Method method : dielectric_methods()) {
        CAPTURE(ggxcl::method_name(method));
        auto smooth = [](const ggxapp::StressCase& c) {
            return c.ax > 0.0f && c.ay > 0.0f && std::max(c.ax, c.ay) <= 1e-3f && !rim_uniform(c) && c.normal.z > -0.99f;
        };
        auto reflecting = dielectric_cases_where(method, axes, [&](const ggxapp::StressCase& c) { return smooth(c) && beyond(c); });
        DielectricSides maps = dielectric_sides(method, reflecting, axes);
        REQUIRE(!reflecting.empty());
        CHECK(total(maps.device, dl::transmitted) == 0);
        CHECK(total(maps.host, dl::transmitted) == 0);
        CHECK(total(maps.cpp, dl::transmitted) == 0);
        CHECK(total(maps.device, dl::invalid) == 0);  // every one a valid reflection
        CHECK(total(maps.host, dl::invalid) == 0);
        CHECK(total(maps.cpp, dl::invalid) == 0);
        auto refracting = dielectric_cases_where(method, axes, [&](const ggxapp::StressCase& c) {
            return smooth(c) && within(c) && c.u3 == 1.0f - 5.9604644775390625e-8f;
        });
        DielectricSides through = dielectric_sides(method, refracting, axes);
        REQUIRE(!refracting.empty());
        CHECK(total(through.device, dl::transmitted) == refracting.size());
        CHECK(total(through.host, dl::transmitted) == refracting.size());
        CHECK(total(through.cpp, dl::transmitted) == refracting.size());
    }
}

// pdf_o / pdf_m of a refraction with c = i.m through an index eta (double; SPEC "Rough dielectrics"):
// the probability 1 - F(c) times the Jacobian eta^2 ct (c + eta ct)^2 / ((eta - 1)(eta + 1))^2, with
// ct = sqrt((eta - 1)(eta + 1) + c^2) / eta.
double refraction_ratio(double c, double eta)
{
    const double d = (eta - 1.0) * (eta + 1.0), ct = std::sqrt(d + c * c) / eta, sum = c + eta * ct;
    const double a = (c - eta * ct) / sum, b = (eta * c - ct) / (eta * c + ct);
    return (1.0 - 0.5 * (a * a + b * b)) * eta * eta * ct * sum * sum / (d * d);
}

TEST_CASE("near eta = 1 a transmission goes straight through: at the floats next to 1, o within 1e-4 of -i and "
          "pdf_o / pdf_m (1 - F) times the Jacobian, up to 1 / (eta - 1)^2, finite")
{
    for (float eta : {1.0f - 0x1p-24f, 1.0f + 0x1p-23f}) {
        ggxapp::StressAxes axes = ggxapp::dielectric_axes({eta});
        for (ggxcl::Method method : dielectric_methods()) {
            CAPTURE(eta);
            CAPTURE(ggxcl::method_name(method));
            auto cases = dielectric_cases_where(method, axes, [&](const ggxapp::StressCase& c) {
                return std::min(c.ax, c.ay) >= 1e-2f && off_grazing(axes, c) && !rim_uniform(c) && c.normal.z > -0.99f;
            });
            std::vector<StressOutcome> outcomes = dl::device_outcomes(sampler(), method, ggxcl::Precision::precise, cases);
            std::uint64_t transmitted = 0, straight = 0, jacobian = 0;
            for (std::size_t j = 0; j < cases.size(); ++j) {
                const StressOutcome& s = outcomes[j];
                const ggxapp::StressCase& c = cases[j];
                if (!dl::classify(s, c)[dl::transmitted])
                    continue;
                ++transmitted;
                const double i[3] = {c.view.x, c.view.y, c.view.z}, n[3] = {c.normal.x, c.normal.y, c.normal.z};
                const bool below = i[0] * n[0] + i[1] * n[1] + i[2] * n[2] < 0.0;
                // From below the device sees 1 / eta rounded to float: 1 / (1 - 2^-24) is 1 + 2^-23.
                const double seen = below ? double(1.0f / eta) : double(eta);
                const double im = std::fabs(s.m[0] * i[0] + s.m[1] * i[1] + s.m[2] * i[2]);
                const double expected = refraction_ratio(im, seen), ratio = s.pdf_o / s.pdf_m;
                straight += std::hypot(s.o[0] + i[0], s.o[1] + i[1], s.o[2] + i[2]) < 1e-4;
                jacobian += std::fabs(ratio - expected) <= 1e-3 * expected && ratio <= 1.001 / ((seen - 1) * (seen - 1));
            }
            CHECK(transmitted > 1000);
            CHECK(straight == transmitted);
            CHECK(jacobian == transmitted);
        }
    }
}
