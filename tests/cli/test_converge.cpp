// test_converge.cpp - `ggx converge` end to end on a small grid (seconds):
//  - every estimate at the largest count lies within 4 of its own standard
//    errors (RMSE / sqrt(R)) of the reference's exact value; control: the
//    same estimates against another integrand's exact value are rejected;
//  - with Sobol points the RMSE of caps' albedo estimate at a smooth
//    configuration falls faster than N^-0.6, with Philox at about N^-0.5
//    (the control: independent points cannot beat plain Monte Carlo);
//  - the CSV and the Markdown report are written; with --charts, a PNG per
//    integrand and one of the time, linked from the report (skipped without
//    a Python with matplotlib: prerequisites.hpp).
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <sstream>

#include "cli_runner.hpp"
#include "prerequisites.hpp"
#include "skip.hpp"

namespace {

namespace fs = std::filesystem;
using ggxtest::read_all;

struct Point {
    std::string method, sequence, integrand;
    double n = 0, rmse = 0, mean = 0, reference = 0, randomizations = 0, slope = 0;
};

std::vector<Point> points_of(const std::string& csv_text)
{
    std::stringstream csv(csv_text);
    std::string line;
    std::getline(csv, line);
    REQUIRE(line == "method,sequence,integrand,alpha,theta_degrees,n,rmse,mean,reference,randomizations,slope");
    std::vector<Point> points;
    while (std::getline(csv, line)) {
        std::stringstream fields(line);
        std::vector<std::string> f;
        for (std::string item; std::getline(fields, item, ',');)
            f.push_back(item);
        REQUIRE(f.size() == 11);
        points.push_back({f[0], f[1], f[2], std::stod(f[5]), std::stod(f[6]), std::stod(f[7]), std::stod(f[8]),
                          std::stod(f[9]), std::stod(f[10])});
    }
    return points;
}

// Whether `p`'s estimate lies within 4 standard errors of `reference`.
bool within_error_bars(const Point& p, double reference)
{
    return std::fabs(p.mean - reference) <= 4.0 * p.rmse / std::sqrt(p.randomizations) + 1e-6 * std::fabs(reference);
}

// `ggx converge` on the small grid, writing c.csv and c.md into `dir`, and `more` arguments.
ggxtest::Run converge(const fs::path& dir, const std::string& more = "")
{
    return ggxtest::run_ggx("converge --methods caps,heitz2017 --alphas 0.3 --thetas 30 --max-n 2^12 "
                            "--randomizations 64 --speed-n 2^16 --csv " + (dir / "c.csv").string() + " --markdown " +
                                (dir / "c.md").string() + more,
                            dir / "stderr.txt");
}

} // namespace

TEST_CASE("ggx converge: estimates within their error bars, Sobol faster than N^-0.6, Philox about N^-0.5")
{
    const ggxtest::ScratchFolder dir("converge");
    ggxtest::Run run = converge(dir.path());
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::vector<Point> points = points_of(read_all(dir / "c.csv"));
    CHECK(points.size() == 2 * 2 * 3 * 9);  // methods x sequences x integrands x counts 2^4 .. 2^12
    std::map<std::string, double> reference_of;
    for (const Point& p : points)
        reference_of[p.integrand] = p.reference;
    int checked = 0, rejected = 0;
    for (const Point& p : points) {
        if (p.n != 4096)
            continue;
        CAPTURE(p.method + " " + p.sequence + " " + p.integrand);
        CAPTURE(p.mean);
        CAPTURE(p.reference);
        CHECK(within_error_bars(p, p.reference));
        ++checked;
        rejected += !within_error_bars(p, reference_of[p.integrand == "albedo" ? "lobe" : "albedo"]);
    }
    CHECK(checked == 12);
    CHECK(rejected == checked);
    for (const Point& p : points)
        if (p.method == "caps" && p.integrand == "albedo" && p.n == 4096) {
            CAPTURE(p.sequence);
            CAPTURE(p.slope);
            if (p.sequence == "sobol")
                CHECK(p.slope < -0.6);
            else
                CHECK((p.slope > -0.6 && p.slope < -0.4));
        }
    const std::string md = read_all(dir / "c.md");
    for (const char* part : {"## albedo", "## lobe", "## disk", "| caps | sobol |",
                             "ggx converge --methods caps,heitz2017"})
        CHECK(md.find(part) != std::string::npos);
    CHECK(md.find(".png") == std::string::npos);  // no charts asked for, none linked
}

TEST_CASE("ggx converge --charts: a PNG per integrand and one of the time, linked from the report")
{
    const ggxtest::ScratchFolder dir("converge");
    if (!ggxtest::skip_unless(ggxtest::plotting_python_present(), ggxtest::plotting_python_reason))
        return;
    ggxtest::Run run = converge(dir.path(), " --charts " + (dir / "c").string());
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::string md = read_all(dir / "c.md");
    for (const char* png : {"c-albedo.png", "c-lobe.png", "c-disk.png", "c-time.png"}) {
        CAPTURE(png);
        CHECK(md.find(png) != std::string::npos);
        CHECK(read_all(dir / png).substr(1, 3) == "PNG");
    }
}
