// test_bench_clock.cpp - `ggx bench` on the selected device reports speeds
// that can be right: every device row's run takes at least a microsecond
// (a driver that fills in no profiling timestamps gave 1 ns for 2^16
// samples), and the report says how the rows were timed: by the events'
// profiling on PoCL, by wall clock on Mesa rusticl, whose timestamps are
// not filled in.
#include <doctest/doctest.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "cli_runner.hpp"

namespace fs = std::filesystem;

namespace {

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
