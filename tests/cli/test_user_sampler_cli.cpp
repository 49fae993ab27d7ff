// test_user_sampler_cli.cpp - `ggx` with --sampler FILE.h, on either API
// (cli_api.hpp: CTest runs it on OpenCL and on Vulkan, where the files are
// read as HLSL): a copy of caps writes caps' samples and passes every
// check; the negative controls fail the checks they must (swapped roughness
// axes: both chi-square tests; a pdf off by 2: the pdf from (i, o) and its
// integral), naming them, with exit 1 under --check; a file that does not
// compile exits 1 naming its file and line; bad flags exit 2 naming the flag.
// `ggx demo --sampler` is skipped without three.js for its page
// (prerequisites.hpp).  Each case works in a folder of its own.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_api.hpp"
#include "cli_reports.hpp"
#include "cli_runner.hpp"
#include "histogram_verdicts.hpp"
#include "prerequisites.hpp"
#include "skip.hpp"

namespace fs = std::filesystem;

namespace {

// The running case's own folder (each case makes one).
const fs::path& scratch()
{
    return ggxtest::ScratchFolder::current();
}

using ggxtest::ggx_on_api;
using ggxtest::user_sampler_file;

} // namespace

TEST_CASE("ggx sample --sampler: a copy of caps writes caps' samples, named for its file")
{
    const ggxtest::ScratchFolder case_folder("user-cli");
    if (!ggxtest::cli_api_present())
        return;
    const fs::path mine = scratch() / "mine.npy", caps = scratch() / "caps.npy";
    const std::string common = " --alpha 0.2,0.5 --theta 75 --sequence sobol -n 3000 --fields m,o,pdf_o,weight,u ";
    const std::string mine_file = user_sampler_file("caps_copy.h");
    REQUIRE(ggx_on_api("sample --sampler " + mine_file + common + "--out " + mine.string()).status == 0);
    REQUIRE(ggx_on_api("sample --method caps" + common + "--out " + caps.string()).status == 0);
    CHECK(ggxtest::read_all(mine) == ggxtest::read_all(caps));
    std::ifstream in(scratch() / "mine.json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    CHECK(doc["method"] == "caps_copy");
    CHECK(doc["sampler_distribution"] == "vndf");
}

TEST_CASE("ggx histogram --sampler: every check passes for a copy of caps, a sampler of m alone too")
{
    const ggxtest::ScratchFolder case_folder("user-cli");
    if (!ggxtest::cli_api_present())
        return;
    for (const std::string file : {"caps_copy.h", "heitz_normal_only.h"}) {
        CAPTURE(file);
        const fs::path prefix = scratch() / "good";
        const ggxtest::Run run = ggx_on_api("histogram --sampler " + user_sampler_file(file) +
                                     " --alpha 0.2,0.6 -n 4e5 --check 1e-3 --no-png --out " + prefix.string());
        CAPTURE(run.err);
        CHECK(run.status == 0);
        const auto got = ggxtest::histogram_verdicts(prefix);
        CHECK(got.size() == ggxtest::all_user_checks("vndf").size());
        for (const auto& [name, verdict] : got) {
            CAPTURE(name);
            CHECK(verdict.passed);
        }
    }
}

TEST_CASE("ggx histogram --sampler: the negative controls fail the checks they must, by name")
{
    const ggxtest::ScratchFolder case_folder("user-cli");
    if (!ggxtest::cli_api_present())
        return;
    for (const ggxtest::HistogramControl& control : ggxtest::histogram_controls()) {
        CAPTURE(control.file);
        const fs::path prefix = scratch() / "control";
        const ggxtest::Run run = ggx_on_api("histogram --sampler " + user_sampler_file(control.file) + " " + control.args +
                                     " -n 4e5 --check 1e-3 --no-png --out " + prefix.string());
        CAPTURE(run.err);
        CHECK(run.status == 1);
        const auto got = ggxtest::histogram_verdicts(prefix);
        for (const std::string& name : control.failing) {
            CAPTURE(name);
            CHECK_FALSE(got.at(name).passed);
            CHECK(run.err.find(name) != std::string::npos);
        }
        for (const std::string& name : control.passing) {
            CAPTURE(name);
            CHECK(got.at(name).passed);
        }
        for (const auto& [name, words] : control.says)
            CHECK_MESSAGE(got.at(name).summary.find(words) != std::string::npos, got.at(name).summary);
    }
}

TEST_CASE("ggx --sampler: a file that does not compile exits 1 naming its file and line; bad flags exit 2")
{
    const ggxtest::ScratchFolder case_folder("user-cli");
    if (!ggxtest::cli_api_present())
        return;
    const ggxtest::Run broken = ggx_on_api("sample --sampler " + user_sampler_file("syntax_error.h") + " -n 10 --out " +
                                    (scratch() / "broken.npy").string());
    CHECK(broken.status == 1);
    // clang names the line that lacks the semicolon, glslang the line of the token after it.
    const std::string line = ggxtest::cli_api().vulkan ? "syntax_error.h:10:" : "syntax_error.h:9:";
    CHECK(broken.err.find(line) != std::string::npos);
    CHECK_FALSE(fs::exists(scratch() / "broken.npy"));
    const std::string file = user_sampler_file("caps_copy.h");
    const std::pair<std::string, std::string> bad[] = {
        {"sample --sampler " + file + " --sampler-name caps", "--sampler-name"},
        {"sample --sampler " + (scratch() / "none.h").string(), "--sampler"},
        {"sample --sampler " + user_sampler_file("../user_samplers/none.h"), "--sampler"},
        {"sample --sampler " + file + " --method caps", "--method"},
        {"sample --sampler " + file + " --eta 1.5", "--eta"},
        {"sample", "--method or --sampler"},
        {"histogram --sampler " + file + " --against ndf", "--against"},
        {"histogram --sampler " + file + " --bins-z 31", "--bins-z"},
    };
    for (const auto& [args, flag] : bad) {
        CAPTURE(args);
        const ggxtest::Run run = ggx_on_api(args + " -n 10 --out " + (scratch() / "bad").string());
        CHECK(run.status == 2);
        CHECK(run.err.find(flag) != std::string::npos);
    }
}

TEST_CASE("ggx stress --sampler: a user sampler's device map beside the methods'; NaN where it divides by zero only")
{
    const ggxtest::ScratchFolder case_folder("user-cli");
    if (!ggxtest::cli_api_present())
        return;
    const fs::path prefix = scratch() / "stress";
    const ggxtest::Run run = ggx_on_api("stress --methods caps --sampler " + user_sampler_file("divides_by_zero.h") +
                                 " --sampler " + user_sampler_file("caps_copy.h") + " --no-png --out " +
                                 prefix.string());
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::string csv = ggxtest::read_all(prefix.string() + ".csv");
    auto [rows, nan_inf] = ggxtest::stress_rows(csv);
    CHECK(rows.size() == 4);  // caps device and host, each user sampler's device
    CHECK(rows.count("caps_copy host") == 0);
    CHECK(rows["caps_copy device"] == rows["caps device"]);
    CHECK(nan_inf["caps device"] == 0);
    CHECK(nan_inf["caps_copy device"] == 0);
    CHECK(nan_inf["divides_by_zero device"] > 0);
    const ggxtest::Run glass = ggx_on_api("stress --sampler " + user_sampler_file("caps_copy.h") + " --eta 1.5 --out " +
                                   prefix.string());
    CHECK(glass.status == 2);
    CHECK(glass.err.find("--eta") != std::string::npos);
}

TEST_CASE("ggx bench --sampler: a copy of caps gets caps' accuracy, philox and Sobol; the pdf self-consistency "
          "catches a pdf off by 2")
{
    const ggxtest::ScratchFolder case_folder("user-cli");
    if (!ggxtest::cli_api_present())
        return;
    const fs::path csv_path = scratch() / "bench.csv";
    const ggxtest::Run run =
        ggx_on_api("bench --methods caps --precisions precise --jobs write,furnace -n 2^14 --repeats 5 --scene 3 "
                   "--cell-samples 2^10 --no-native --no-startup --sampler " + user_sampler_file("caps_copy.h") +
                   " --reproduces caps --sampler " + user_sampler_file("pdf_doubled.h") + " --csv " + csv_path.string());
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::string csv = ggxtest::read_all(csv_path);
    std::map<std::string, std::string> cells;  // "method job column", "method job sobol column": precise rows
    for (const ggxtest::BenchCsvRow& row : ggxtest::bench_csv_rows(csv)) {
        CAPTURE(row.line);
        CHECK(ggxtest::csv_cell(csv, row.line, "api") == ggxtest::cli_api().label);
        const std::string sequence = ggxtest::csv_cell(csv, row.line, "sequence");
        const std::string key = row.method + " " + row.job + (sequence == "philox" ? "" : " " + sequence);
        if (row.precision == "precise")
            for (const char* column : {"ns_median", "angle_p99", "pdf_rel_max", "albedo_variance", "mean_albedo",
                                       "rmse_measured", "pdf_disagreement"})
                cells[key + " " + column] = ggxtest::csv_cell(csv, row.line, column);
    }
    for (const std::string sequence : {"", " sobol"})
        for (const std::string column : {"angle_p99", "pdf_rel_max"}) {
            CAPTURE(sequence + column);
            CHECK_FALSE(cells["caps write" + sequence + " " + column].empty());
            CHECK(cells["caps_copy write" + sequence + " " + column] == cells["caps write" + sequence + " " + column]);
            CHECK(cells["pdf_doubled write" + sequence + " " + column].empty());  // reproduces no map: not measured
        }
    for (const std::string column : {"albedo_variance", "mean_albedo"}) {  // the RMSE's sample count is its speed's
        CAPTURE(column);
        CHECK(cells["caps_copy furnace " + column] == cells["caps furnace " + column]);
    }
    for (const std::string key : {"caps_copy write ns_median", "caps_copy write sobol ns_median",
                                  "caps_copy furnace rmse_measured", "caps_copy furnace sobol rmse_measured",
                                  "caps furnace sobol rmse_measured"}) {
        CAPTURE(key);
        CHECK(std::stod(cells[key]) > 0.0);
    }
    CHECK(cells["caps write pdf_disagreement"].empty());
    CHECK(std::stod(cells["caps_copy write pdf_disagreement"]) == 0.0);
    CHECK(std::stod(cells["pdf_doubled write pdf_disagreement"]) == 1.0);
    CHECK(cells["caps_copy write sobol pdf_disagreement"].empty());  // on philox alone
    const ggxtest::Run bad = ggx_on_api("bench --sampler " + user_sampler_file("caps_copy.h") + " --reproduces walter");
    CHECK(bad.status == 2);
    CHECK(bad.err.find("--reproduces") != std::string::npos);
}

TEST_CASE("ggx converge --sampler: a copy of caps converges as caps, with philox and sobol")
{
    const ggxtest::ScratchFolder case_folder("user-cli");
    if (!ggxtest::cli_api_present())
        return;
    const fs::path csv_path = scratch() / "converge.csv";
    const ggxtest::Run run = ggx_on_api("converge --methods caps --sampler " + user_sampler_file("caps_copy.h") +
                                 " --integrands albedo,disk --alphas 0.3 --thetas 45 --max-n 2^10 --randomizations 8 "
                                 "--no-speed --csv " + csv_path.string());
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    auto curves = ggxtest::converge_curves(csv_path);
    REQUIRE(curves["caps"].size() > 10);
    CHECK(curves["caps_copy"] == curves["caps"]);
}

TEST_CASE("ggx demo --sampler: the user sampler's cloud, histogram and row beside the methods'")
{
    const ggxtest::ScratchFolder case_folder("user-cli");
    if (!ggxtest::cli_api_present())
        return;
    if (!ggxtest::skip_unless(ggxtest::three_js_present(), ggxtest::three_js_reason))
        return;
    const fs::path out = scratch() / "demo";
    const ggxtest::Run run = ggx_on_api("demo -n 300 --histogram-n 2e4 --no-png --sampler " +
                                 user_sampler_file("caps_copy.h") + " --sampler-name mine --out " + out.string());
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::string page = ggxtest::read_all(out / "index.md");
    CHECK(page.find("| mine |") != std::string::npos);
    CHECK(page.find("| caps |") != std::string::npos);
    if (ggxtest::cli_api().vulkan)  // the page names an API other than the default
        CHECK(page.find(ggxtest::cli_api().label) != std::string::npos);
    for (const char* file : {"mine.npy", "mine.ply", "mine.hist.json", "mine.hist.observed.npy"})
        CHECK(fs::exists(out / file));
    CHECK(ggx_on_api("demo --eta 1.5 --sampler " + user_sampler_file("caps_copy.h") + " --out " + out.string()).status == 2);
}

TEST_CASE("ggx stress --isotropic-samplers: a user sampler mapped on isotropic roughness alone")
{
    const ggxtest::ScratchFolder case_folder("user-cli");
    if (!ggxtest::cli_api_present())
        return;
    const ggxtest::Run run = ggx_on_api("stress --methods caps --sampler " + user_sampler_file("caps_copy.h") +
                                 " --isotropic-samplers --no-png --out " + (scratch() / "iso").string());
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::string csv = ggxtest::read_all(scratch() / "iso.csv");
    auto cases_of = [&](const std::string& row) {  // the cases column summed over the device's cells
        long total = 0;
        std::stringstream lines(csv);
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind(row + ",device,", 0) != 0)
                continue;
            std::stringstream cells(line);
            std::string cell;
            for (int column = 0; column < 6; ++column)
                std::getline(cells, cell, ',');
            total += std::stol(cell);
        }
        return total;
    };
    CHECK(cases_of("caps") > 0);
    // caps' roughness pairs are (a, a), (a, a/1000), (a/1000, a), (0, a), (a, 0): the copy keeps the first.
    CHECK(cases_of("caps_copy") * 5 == cases_of("caps"));
    const ggxtest::Run alone = ggx_on_api("stress --methods caps --isotropic-samplers --no-png --out " +
                                   (scratch() / "none").string());
    CHECK(alone.status == 2);
    CHECK(alone.err.find("--isotropic-samplers") != std::string::npos);
}
