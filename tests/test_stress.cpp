// test_stress.cpp - the stability map (`ggx stress`): its classification of
// one outcome by failure kind on hand-made outcomes, and the tool's CSV
// (one row per method, side and cell; every cell with all its cases; no
// count above the cases) and bad input.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "cli_runner.hpp"
#include "stress_run.hpp"

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
    s.m[2] = 1.001;
    CHECK(kinds_of(s) == Names{"not_unit"});
    s = good();
    s.m[2] = -1.0;
    CHECK(kinds_of(s) == Names{"m_below"});
    s = good();
    s.o[2] = -s.o[2];
    CHECK(kinds_of(s) == Names{"wasted"});  // a wasted sample's pdf is not judged
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
    CHECK(line == "method,side,precision,alpha,theta_degrees,cases,nan_inf,not_unit,m_below,wasted,"
                  "pdf_nonpositive,pdf_mismatch");
    int rows = 0;
    while (std::getline(csv, line)) {
        std::stringstream fields(line);
        std::vector<std::string> f;
        std::string field;
        while (std::getline(fields, field, ','))
            f.push_back(field);
        REQUIRE(f.size() == 12);
        CAPTURE(line);
        long cases = std::stol(f[5]);
        CHECK(cases == 85);  // caps: 5 roughness pairs x 17 uniform pairs; caps-iso: 5 normals x 17
        for (int k = 6; k < 12; ++k)
            CHECK(std::stol(f[k]) <= cases);
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
