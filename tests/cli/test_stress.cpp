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

#include <cmath>
#include <limits>
#include <sstream>

#include "cli_runner.hpp"
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

// Totals of one kind over a map.
std::uint64_t total(const ggxapp::StressMap& map, int kind)
{
    std::uint64_t n = 0;
    for (const ggxapp::CellCounts& cell : map)
        n += kind < 0 ? cell.cases : cell.failures[kind];
    return n;
}

// The cases of the full grid that `keep` selects.
template <class Keep>
std::vector<ggxapp::StressCase> cases_where(ggxcl::Method method, const ggxapp::StressAxes& axes, Keep keep)
{
    std::vector<ggxapp::StressCase> kept;
    for (const ggxapp::StressCase& c : ggxapp::stress_cases(method, axes))
        if (keep(c))
            kept.push_back(c);
    return kept;
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
    return {ggxapp::device_stress_map(sampler(), method, ggxcl::Precision::precise, cases, axes),
            ggxapp::host_stress_map(method, cases, axes), ggxapp::cpp_stress_map(method, cases, axes)};
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
                  "pdf_nonpositive,pdf_mismatch");
    int rows = 0;
    while (std::getline(csv, line)) {
        std::stringstream fields(line);
        std::vector<std::string> f;
        std::string field;
        while (std::getline(fields, field, ','))
            f.push_back(field);
        REQUIRE(f.size() == 13);
        CAPTURE(line);
        long cases = std::stol(f[5]);
        CHECK(cases == 90);  // caps: 5 roughness pairs x 18 uniform pairs; caps-iso: 5 normals x 18
        for (int k = 6; k < 13; ++k)
            CHECK(std::stol(f[k]) <= cases);
        CHECK(f[6] == "0");  // no NaN or Inf anywhere
        ++rows;
    }
    CHECK(rows == 2 * 2 * 19 * 13);  // 2 methods x (device, host) x 19 alphas x 13 views
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
        {"stress --out /no/such/folder/m", "--out"},
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
        ggxtest::run_ggx("{ " + std::string(GGX_BINARY) + " stress --help 1>&2; }", dir / "help.txt", false);
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
        for (ggxcl::Precision precision : ggxcl::all_precisions) {
            CAPTURE(ggxcl::precision_name(precision));
            CHECK(total(ggxapp::device_stress_map(sampler(), method, precision, cases, axes), ggxapp::nan_inf) == 0);
        }
        CHECK(total(ggxapp::host_stress_map(method, cases, axes), ggxapp::nan_inf) == 0);
        CHECK(total(ggxapp::cpp_stress_map(method, cases, axes), ggxapp::nan_inf) == 0);
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
            if (kind == ggxapp::wasted)
                continue;  // not a failure
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
