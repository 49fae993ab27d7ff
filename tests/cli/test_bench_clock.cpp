// test_bench_clock.cpp - `ggx bench` on the selected device reports speeds
// that can be right: every device row's run takes at least a microsecond
// (a driver that fills in no profiling timestamps gave 1 ns for 2^16
// samples), and the report says how the rows were timed: by the events'
// profiling on PoCL, by wall clock on Mesa rusticl, whose timestamps are
// not filled in.  With --eta, a rough dielectric's rows beside the
// conductor's for every exact method, and bounded's note.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace fs = std::filesystem;

namespace {

using ggxtest::csv_cell;

std::string selected_device()
{
    const char* chosen = std::getenv("GGXCL_DEVICE");
    return chosen ? chosen : "";
}

} // namespace

TEST_CASE("ggx bench times device rows by a clock that can be right, and says which")
{
    fs::path dir = ggxtest::scratch_dir("bench-clock");
    const std::uint64_t count = 1u << 16;
    ggxtest::Run run = ggxtest::run_ggx("bench --methods caps,heitz --precisions precise --jobs write,furnace -n 2^16 "
                                        "--repeats 5 --no-native --no-accuracy --no-startup --csv " +
                                            (dir / "b.csv").string() + " --markdown " + (dir / "B.md").string(),
                                        dir / "stderr.txt");
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    int rows = 0;
    for (const ggxtest::BenchCsvRow& row : ggxtest::bench_csv_rows(ggxtest::read_all(dir / "b.csv"))) {
        CAPTURE(row.line);
        CHECK(row.ns_median * double(count) >= 1000.0);  // a run of 2^16 samples takes at least 1 us
        ++rows;
    }
    CHECK(rows >= 4);
    std::string md = ggxtest::read_all(dir / "B.md");
    const std::string device = selected_device();
    CAPTURE(device);
    if (device.find("rusticl") != std::string::npos) {
        CHECK(md.find("wall-clock (launch to finish") != std::string::npos);
        CHECK(run.err.find("timed by wall clock") != std::string::npos);
    } else if (device.empty() || device.find("Portable") != std::string::npos || device == "0") {
        CHECK(md.find("runs after a warm-up, event-profiled") != std::string::npos);  // PoCL's timestamps are right
    } else {
        CHECK((md.find("event-profiled") != std::string::npos || md.find("wall-clock") != std::string::npos));
    }
}

TEST_CASE("ggx bench --eta puts a dielectric's rows beside the conductor's for every exact method")
{
    fs::path dir = ggxtest::scratch_dir("bench-eta");
    ggxtest::Run run = ggxtest::run_ggx("bench --eta 1.5 --precisions precise --jobs write,furnace -n 2^14 --repeats 5 "
                                        "--no-native --no-startup --scene 2 --cell-samples 2^8 --sequences philox --csv " +
                                            (dir / "b.csv").string() + " --markdown " + (dir / "B.md").string(),
                                        dir / "stderr.txt");
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::string csv = ggxtest::read_all(dir / "b.csv");
    for (const char* method : {"ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded"}) {
        CAPTURE(method);
        int conductor_o = 0, dielectric_o = 0, dielectric_furnace = 0, conductor_furnace = 0;
        for (const ggxtest::BenchCsvRow& row : ggxtest::bench_csv_rows(csv)) {
            if (row.method != method)
                continue;
            CAPTURE(row.line);
            const bool dielectric = csv_cell(csv, row.line, "eta") == "1.5";
            CHECK((dielectric || csv_cell(csv, row.line, "eta") == "0"));
            CHECK(csv_cell(csv, row.line, "transport") == (dielectric ? "radiance" : ""));
            conductor_o += row.job == "write-o" && !dielectric;
            dielectric_o += row.job == "write-o" && dielectric;
            conductor_furnace += row.job == "furnace" && !dielectric;
            dielectric_furnace += row.job == "furnace" && dielectric;
            if (row.job == "furnace" && dielectric)  // the reflectance and transmittance within 6 standard errors
                for (const char* part : {"reflectance", "transmittance"}) {
                    const double error = std::stod(csv_cell(csv, row.line, part)) -
                                         std::stod(csv_cell(csv, row.line, std::string(part) + "_exact"));
                    CHECK(std::fabs(error) < 6.0 * std::stod(csv_cell(csv, row.line, std::string(part) + "_se")));
                }
        }
        const int exact = std::string(method) == "bounded" ? 0 : 1;  // bounded: no dielectric sampler
        CHECK(conductor_o == exact);
        CHECK(dielectric_o == exact);
        CHECK(dielectric_furnace == exact);
        CHECK(conductor_furnace == 1);
    }
    const std::string md = ggxtest::read_all(dir / "B.md");
    CHECK(md.find("## Rough dielectric: eta 1.5, radiance transport") != std::string::npos);
    for (const char* method : {"ndf", "heitz", "heitz2017", "caps", "caps-iso"}) {
        CAPTURE(method);
        CHECK(md.find("| " + std::string(method) + " | precise | write o + pdf_o | ") != std::string::npos);
        CHECK(md.find("| " + std::string(method) + " | precise | fused furnace | ") != std::string::npos);
    }
    CHECK(md.find("| bounded | precise | fused furnace |") == std::string::npos);
    CHECK(md.find("bounded: no dielectric rows; it has no exact dielectric sampler") != std::string::npos);
    CHECK(md.find("ggxref::dielectric_albedo: R = ") != std::string::npos);
}
