// test_cli.cpp - the `ggx` tool end to end: `sample` writes a .npy of the
// requested columns and a JSON sidecar that read back correctly, `demo`
// writes every method (with --eta, a dielectric's), and bad input exits 2 with a one-line message naming
// the flag and leaves no file behind.  Each case works in a folder of its own; the demo's page
// needs three.js, bench's charts a Python with matplotlib and its limits clang, the symbol check
// nm: without them those cases are skipped (prerequisites.hpp, skip.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include <ggxcl/ggxcl.hpp>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "ggx_reference.hpp"
#include "npy_file.hpp"
#include "prerequisites.hpp"
#include "skip.hpp"

namespace fs = std::filesystem;

namespace {

using ggxtest::csv_cell;
using ggxtest::read_all;
using ggxtest::Run;

// The running case's own folder (each case makes one).
const fs::path& scratch()
{
    return ggxtest::ScratchFolder::current();
}

using ggxtest::ggx;

bool only_file_is(const fs::path& dir, std::size_t expected)
{
    std::size_t n = 0;
    for (const auto& entry : fs::directory_iterator(dir))
        n += entry.path().filename() != "stderr.txt" && entry.path().filename() != "inputs";
    return n == expected;
}

// A float64 .npy of `rows` x `columns` values 0.5 but entry `bad` (row-major) = `value`,
// in the inputs folder (not counted as output); its path.
std::string bad_uniforms(const std::string& name, std::size_t rows, std::size_t columns, std::size_t bad, double value)
{
    fs::path dir = scratch() / "inputs";
    fs::create_directories(dir);
    std::vector<double> data(rows * columns, 0.5);
    data[bad] = value;
    ggxapp::write_npy_f64((dir / name).string(), rows, columns, data);
    return (dir / name).string();
}

} // namespace

TEST_CASE("ggx sample writes the requested columns and a sidecar")
{
    const ggxtest::ScratchFolder case_folder("cli");
    fs::path out = scratch() / "s.npy";
    Run run = ggx("sample --method bounded --alpha 0.2,0.4 --theta 70 --phi 15 -n 2^12 --seed 11 --first 5 "
                  "--fields o,pdf_o,m --out " + out.string());
    REQUIRE(run.status == 0);
    ggxapp::NpyArray a = ggxapp::read_npy(out.string());
    CHECK(a.rows == 4096);
    CHECK(a.columns == 7);
    std::size_t bad = 0;
    for (std::size_t j = 0; j < a.rows; ++j) {
        const float* row = &a.data[j * 7];
        bad += std::fabs(std::hypot(row[0], row[1], row[2]) - 1.0) > 1e-5;  // o unit
        bad += !(row[3] > 0.0f);                                            // pdf_o positive
        bad += std::fabs(std::hypot(row[4], row[5], row[6]) - 1.0) > 1e-5;  // m unit
        bad += !(row[6] > 0.0f);                                            // m above the surface
    }
    CHECK(bad == 0);
    nlohmann::json doc = nlohmann::json::parse(std::ifstream((scratch() / "s.json").string()));
    CHECK(doc["method"] == "bounded");
    CHECK(doc["seed"] == 11);
    CHECK(doc["first"] == 5);
    CHECK(doc["count"] == 4096);
    CHECK(doc["columns"] == nlohmann::json({"o_x", "o_y", "o_z", "pdf_o", "m_x", "m_y", "m_z"}));
    CHECK(doc["alpha"][1].get<double>() == doctest::Approx(0.4));
    CHECK(!doc["device"].get<std::string>().empty());
    CHECK(!doc["ggxcl_version"].get<std::string>().empty());
    fs::remove(out);
    fs::remove(scratch() / "s.json");
}

TEST_CASE("ggx sample --uniforms draws from the caller's uniforms; --sequence sobol is recorded")
{
    const ggxtest::ScratchFolder case_folder("cli");
    const std::uint64_t n = 3000, seed = 4;
    fs::path dir = scratch() / "uniforms";
    fs::create_directories(dir);
    std::vector<double> u64(2 * n);
    std::vector<float> u32(2 * n);
    for (std::uint64_t j = 0; j < n; ++j)
        for (int c = 0; c < 2; ++c)
            u32[2 * j + c] = float(u64[2 * j + c] = ggxref::sobol_uniforms(seed, j)[c]);
    ggxapp::write_npy_f64((dir / "u64.npy").string(), n, 2, u64);
    ggxapp::NpyWriter f32((dir / "u32.npy").string(), n, 2);
    f32.append(u32);
    f32.commit();
    const std::string common = "sample --method heitz --alpha 0.2,0.5 --theta 40 --fields m,o,pdf_o,u --out ";
    REQUIRE(ggx(common + (dir / "seq.npy").string() + " --sequence sobol --seed 4 -n 3000").status == 0);
    REQUIRE(ggx(common + (dir / "f64.npy").string() + " --uniforms " + (dir / "u64.npy").string()).status == 0);
    REQUIRE(ggx(common + (dir / "f32.npy").string() + " --uniforms " + (dir / "u32.npy").string() + " -n 3000")
                .status == 0);
    ggxapp::NpyArray sequence = ggxapp::read_npy((dir / "seq.npy").string());
    CHECK(sequence.columns == 9);
    CHECK(sequence.data == ggxapp::read_npy((dir / "f64.npy").string()).data);
    CHECK(sequence.data == ggxapp::read_npy((dir / "f32.npy").string()).data);
    CHECK(sequence.data[7] == u32[0]);  // the u columns
    CHECK(sequence.data[9 * 2999 + 8] == u32[2 * 2999 + 1]);
    nlohmann::json seq = nlohmann::json::parse(read_all(dir / "seq.json"));
    CHECK(seq["sequence"] == "sobol");
    CHECK(seq["columns"].back() == "u2");
    CHECK(seq["generator"].get<std::string>().find("Owen-scrambled") != std::string::npos);
    nlohmann::json given = nlohmann::json::parse(read_all(dir / "f64.json"));
    CHECK(given.count("sequence") == 0);
    CHECK(given["generator"].get<std::string>().find("u64.npy") != std::string::npos);
    CHECK(given["count"] == n);
    // Control: the default sequence gives other samples.
    REQUIRE(ggx(common + (dir / "philox.npy").string() + " --seed 4 -n 3000").status == 0);
    CHECK(sequence.data != ggxapp::read_npy((dir / "philox.npy").string()).data);
    CHECK(nlohmann::json::parse(read_all(dir / "philox.json"))["sequence"] == "philox");
    fs::remove_all(dir);
}

TEST_CASE("ggx demo writes clouds, histograms and a summary page for every method")
{
    const ggxtest::ScratchFolder case_folder("cli");
    if (!ggxtest::skip_unless(ggxtest::three_js_present(), ggxtest::three_js_reason))
        return;
    fs::path dir = scratch() / "demo";
    REQUIRE(ggx("demo -n 1000 --histogram-n 1e5 --no-png --out " + dir.string()).status == 0);
    std::string page = read_all(dir / "index.md");
    for (const char* method : {"ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded"}) {
        CAPTURE(method);
        ggxapp::NpyArray a = ggxapp::read_npy((dir / (std::string(method) + ".npy")).string());
        CHECK(a.rows == 1000);
        CHECK(fs::exists(dir / (std::string(method) + ".json")));
        CHECK(fs::exists(dir / (std::string(method) + ".ply")));
        nlohmann::json h = nlohmann::json::parse(read_all(dir / (std::string(method) + ".hist.json")));
        CHECK(h["p_value"].get<double>() > 1e-4);
        CHECK(page.find("| " + std::string(method) + " |") != std::string::npos);
    }
    CHECK(page.find("binning in precise mode (the default)") != std::string::npos);  // the mode of the throughput
    CHECK(page.find("uniforms from the philox sequence (the default)") != std::string::npos);
    CHECK(page.find("transport") == std::string::npos);  // a conductor: no eta, no transport
    fs::remove_all(dir);
}

TEST_CASE("ggx demo --eta writes a rough dielectric's clouds and whole-sphere histograms for every method but bounded")
{
    const ggxtest::ScratchFolder case_folder("cli");
    if (!ggxtest::skip_unless(ggxtest::three_js_present(), ggxtest::three_js_reason))
        return;
    fs::path dir = scratch() / "demo-eta";
    REQUIRE(ggx("demo --eta 1.5 --transport importance -n 1000 --histogram-n 1e5 --no-png --out " + dir.string())
                .status == 0);
    std::string page = read_all(dir / "index.md");
    for (const char* method : {"ndf", "heitz", "heitz2017", "caps", "caps-iso"}) {
        CAPTURE(method);
        ggxapp::NpyArray a = ggxapp::read_npy((dir / (std::string(method) + ".npy")).string());
        REQUIRE(a.rows == 1000);
        REQUIRE(a.columns == 8);  // m, o, pdf_o, weight
        std::size_t below = 0;
        for (std::size_t j = 0; j < a.rows; ++j)
            below += a.data[j * 8 + 5] < 0.0f;  // o refracted below the surface
        CHECK(below > 100);
        CHECK(fs::exists(dir / (std::string(method) + ".ply")));
        nlohmann::json h = nlohmann::json::parse(read_all(dir / (std::string(method) + ".hist.json")));
        CHECK(h["eta"].get<double>() == doctest::Approx(1.5));
        CHECK(h["transport"] == "importance");
        CHECK(h.contains("invalid_samples"));
        CHECK(h["p_value"].get<double>() > 1e-4);
        CHECK(page.find("| " + std::string(method) + " |") != std::string::npos);
    }
    CHECK_FALSE(fs::exists(dir / "bounded.npy"));
    CHECK(page.find("| bounded |") == std::string::npos);
    CHECK(page.find("bounded is left out: it has no exact dielectric sampler") != std::string::npos);
    CHECK(page.find("seed 0, eta 1.5, importance transport;") != std::string::npos);
    CHECK(page.find("over the whole sphere") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("bad input exits 2 with a message naming the flag and leaves no file")
{
    const ggxtest::ScratchFolder case_folder("cli");
    const std::string out = " --out " + (scratch() / "bad.npy").string();
    struct Case {
        std::string args, flag;
    } cases[] = {
        {"sample --method walter -n 10" + out, "--method"},
        {"sample --method caps --alpha 0 -n 10" + out, "--alpha"},
        {"sample --method caps --alpha nan -n 10" + out, "--alpha"},
        {"sample --method caps --alpha 0.1,-2 -n 10" + out, "--alpha"},
        {"sample --method caps --alpha 9e-69 -n 10" + out, "--alpha"},  // rounds to a float 0 (found by fuzzing)
        {"sample --method caps-iso --alpha 0.1,0.2 -n 10" + out, "--alpha"},
        {"sample --method caps --theta 181 -n 10" + out, "--theta"},
        {"sample --method caps --theta -1 -n 10" + out, "--theta"},
        {"sample --method caps -n 0" + out, "-n"},
        {"sample --method caps -n -5" + out, "-n"},
        {"sample --method caps -n ten" + out, "-n"},
        {"sample --method caps -n 10 --seed 4294967296" + out, "--seed"},  // the 32-bit key of Philox2x32
        {"sample --method caps -n 2^63 --first 18446744073709551615" + out, "-n"},  // found by fuzz_cli
        {"sample --method caps -n 10 --fields m,x" + out, "--fields"},
        {"sample --method caps --normal 0,0,1 -n 10" + out, "--normal"},
        {"sample --method caps-iso --normal 0,0,0 -n 10" + out, "--normal"},
        {"sample --method caps -n 10 --out /dev/null/no-folder/x.npy", "--out"},
        {"sample --method caps -n 10 --out " + (scratch() / "x.txt").string(), "--out"},
        {"sample --method caps -n 10 --fields m,o --out " + (scratch() / "x.ply").string(), "--fields"},
        {"sample --method caps -n 10 --device no-such-device" + out, "--device"},
        {"sample --method caps -n 10 --devices 0,no-such-device" + out, "--device"},
        {"sample --method caps -n 10 --sequence halton" + out, "--sequence"},
        {"sample --method caps" + out, "-n"},
        {"sample --method caps --uniforms " + (scratch() / "missing.npy").string() + out, "--uniforms"},
        {"sample --method caps --uniforms " + bad_uniforms("three.npy", 4, 3, 3, 0.5) + out, "--uniforms"},
        {"sample --method caps --uniforms " + bad_uniforms("one.npy", 4, 2, 5, 1.0) + out, "row 2: 0.5,1"},
        {"sample --method caps --uniforms " + bad_uniforms("nan.npy", 4, 2, 6, std::nan("")) + out, "row 3"},
        {"sample --method caps -n 5 --uniforms " + bad_uniforms("ok.npy", 4, 2, 0, 0.5) + out, "-n"},
        {"sample --method caps --sequence sobol --uniforms " + bad_uniforms("ok.npy", 4, 2, 0, 0.5) + out,
         "--sequence"},
        {"sample --method caps --devices 0,0 --uniforms " + bad_uniforms("ok.npy", 4, 2, 0, 0.5) + out, "--uniforms"},
        {"histogram --method walter" + out, "--method"},
        {"histogram --method caps --alpha 0" + out, "--alpha"},
        {"histogram --method caps --theta 200" + out, "--theta"},
        {"histogram --method caps -n 0" + out, "-n"},
        {"histogram --method caps -n 2 --first 18446744073709551615" + out, "-n"},
        {"histogram --method caps --check 1.5" + out, "--check"},
        {"histogram --method caps --bins-z 0" + out, "--bins-z"},
        {"histogram --method caps --bins-phi x" + out, "--bins-phi"},
        {"histogram --method caps --against nope" + out, "--against"},
        {"histogram --method caps --of x" + out, "--of"},
        {"histogram --method caps --precision turbo" + out, "--precision"},
        {"histogram --method caps --sequence sobel" + out, "--sequence"},
        {"bench --repeats 2", "--repeats"},
        {"bench --methods walter", "--methods"},
        {"bench --methods caps,", "--methods"},
        {"bench --precisions turbo", "--precisions"},
        {"bench --jobs write,read", "--jobs"},
        {"bench --sequences philox,halton", "--sequences"},
        {"bench --alpha 0.2,0.5", "--alpha"},
        {"bench --theta 95", "--theta"},
        {"bench --scene 1", "--scene"},
        {"bench -n 2^31", "-n"},
        {"bench --csv /dev/null/no-folder/b.csv", "--csv"},
        {"bench --eta 1", "--eta"},
        {"bench --eta 1.5 --transport sideways", "--transport"},
        {"converge --max-n 1000", "--max-n"},
        {"converge --min-n 2^10 --max-n 2^11", "--max-n"},
        {"converge --alphas 0.3,0", "--alphas"},
        {"converge --thetas 95", "--thetas"},
        {"converge --sequences sobol,halton", "--sequences"},
        {"converge --integrands albedo,sphere", "--integrands"},
        {"converge --randomizations 2", "--randomizations"},
        {"converge --csv /dev/null/no-folder/c.csv", "--csv"},
        {"devices --verbose", "--verbose"},
        {"histogram --method caps --out /dev/null/no-folder/h", "--out"},
        {"demo -n 0 --no-html --out " + (scratch() / "d").string(), "-n"},  // no page: three.js not needed
        {"demo --alpha -1 --no-html --out " + (scratch() / "d").string(), "--alpha"},
        {"demo --eta 1 --no-html --out " + (scratch() / "d").string(), "--eta"},
        {"demo --eta 1.5 --transport sideways --no-html --out " + (scratch() / "d").string(), "--transport"},
        {"merge --out " + (scratch() / "m.txt").string() + " a.npy", "--out"},
        {"merge --out " + (scratch() / "m.npy").string() + " missing.npy", "SHARD"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.args);
        Run run = ggx(c.args);
        CAPTURE(run.err);
        CHECK(run.status == 2);
        CHECK(run.err.find(c.flag) != std::string::npos);
        CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
        CHECK(only_file_is(scratch(), 0));
    }
}

// The library's refusal of `p` (its InvalidArgument's "allowed" text).
std::string library_rule(const ggxcl::SampleParams& p)
{
    try {
        ggxcl::validate(p);
    } catch (const ggxcl::InvalidArgument& error) {
        return error.allowed();
    }
    return "(accepted)";
}

TEST_CASE("the CLI reports the library's rules in the library's words, naming the option and quoting its text")
{
    const ggxtest::ScratchFolder case_folder("cli");
    const std::string out = " -n 10 --out " + (scratch() / "rule.npy").string();
    ggxcl::SampleParams tiny, iso, glass;
    tiny.alpha_x = tiny.alpha_y = 1e-35f;
    iso.method = ggxcl::Method::caps_iso;
    iso.alpha_y = 0.2f;
    glass.method = ggxcl::Method::bounded;
    glass.eta = 1.5f;
    struct Case {
        std::string args, expected;
    } cases[] = {
        {"sample --method caps --alpha 1e-35" + out, "--alpha: invalid value '1e-35': allowed is " + library_rule(tiny)},
        {"sample --method caps-iso --alpha 0.3,0.2" + out,
         "--alpha: invalid value '0.3,0.2': allowed is " + library_rule(iso)},
        {"sample --method bounded --eta 1.5" + out, "--eta: invalid value '1.5': allowed is " + library_rule(glass)},
        {"sample --method caps --theta 200" + out, "--theta: invalid value '200': allowed is degrees from 0 to 180"},
    };
    CHECK(library_rule(tiny) == "a number from 1e-30 to 1e30");
    for (const Case& c : cases) {
        CAPTURE(c.args);
        Run run = ggx(c.args);
        CHECK(run.status == 2);
        CHECK(run.err == "ggx: " + c.expected + "\n");
    }
}

TEST_CASE("the CLI names a bad value before a missing one, the nearest command or option, and speaks its own words")
{
    const ggxtest::ScratchFolder case_folder("cli");
    struct Case {
        std::string args, expected;
    } cases[] = {
        {"sample --method capz", "ggx: --method: invalid value 'capz': allowed is one of " + ggxcl::method_list()},
        {"sample --method caps", "ggx: -n is required (or --uniforms, whose rows give the count)"},
        {"sample --method caps -n 10", "ggx: --out is required: the .npy, .csv or .ply file to write"},
        {"histogram --method caps --alpha 0", "ggx: --alpha: invalid value '0': allowed is a number from 1e-30 to 1e30"},
        {"histogram --method caps", "ggx: --out is required: a path prefix such as results/caps"},
        {"sampel --method caps", "ggx: unknown command 'sampel'; did you mean 'sample'? (the commands: devices, "
                                 "methods, sample, histogram, demo, merge, bench, converge, stress)"},
        {"sample --method caps --method ndf", "ggx: --method: given 2 times; allowed is once"},
        {"sample --methd caps", "ggx: unknown option '--methd'; did you mean '--method'? (see the command's --help)"},
        {"sample --method caps -n", "ggx: --count: its value is missing"},
        {"", "ggx: a command is required: one of devices, methods, sample, histogram, demo, merge, bench, converge, "
             "stress (see ggx --help)"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.args);
        Run run = ggx(c.args);
        CHECK(run.status == 2);
        CHECK(run.err == c.expected + "\n");
    }
}

TEST_CASE("every command makes the folder of its output; --help shows each value's kind and default")
{
    const ggxtest::ScratchFolder case_folder("cli");
    const fs::path out = scratch() / "fresh" / "deeper" / "x.npy";
    Run run = ggx("sample --method caps -n 10 --out " + out.string());
    CAPTURE(run.err);
    CHECK(run.status == 0);
    CHECK(fs::is_regular_file(out));
    const fs::path help = scratch() / "help.txt";
    run = ggxtest::run_ggx("{ " + ggxtest::ggx_binary() + " histogram --help >" + help.string() + "; }",
                           scratch() / "stderr.txt", false);
    REQUIRE(run.status == 0);
    const std::string text = read_all(help);
    CHECK(text.find("-n,--count COUNT=1e6") != std::string::npos);
    CHECK(text.find("--theta DEGREES=60") != std::string::npos);
    CHECK(text.find("--out PATH ") != std::string::npos);
    CHECK(text.find(" TEXT") == std::string::npos);  // CLI11's name for any string
    // The ranges as the library states them (params.hpp), not copies.
    CHECK(text.find(std::string("each ") + ggxcl::alpha_range) != std::string::npos);
    CHECK(text.find(std::string("uniforms, ") + ggxcl::seed_range) != std::string::npos);
    fs::remove_all(scratch() / "fresh");
}

TEST_CASE("ggx methods prints the table of methods (the README's: test_readme_methods); --names the names alone")
{
    const ggxtest::ScratchFolder case_folder("cli");
    const fs::path names = scratch() / "names.txt";
    REQUIRE(ggxtest::run_ggx("{ " + ggxtest::ggx_binary() + " methods --names >" + names.string() + "; }",
                             scratch() / "stderr.txt", false)
                .status == 0);
    std::string expected_names;
    for (const ggxcl::MethodTraits& t : ggxcl::method_table)
        expected_names += std::string(t.name) + "\n";
    CHECK(read_all(names) == expected_names);
    const fs::path table = scratch() / "methods.md";
    Run run = ggxtest::run_ggx("{ " + ggxtest::ggx_binary() + " methods >" + table.string() + "; }",
                               scratch() / "stderr.txt", false);
    REQUIRE(run.status == 0);
    const std::string out = read_all(table);
    for (const ggxcl::MethodTraits& t : ggxcl::method_table) {
        CHECK(out.find("| `" + std::string(t.name) + "` | " + std::string(t.paper)) != std::string::npos);
        if (!t.limits.empty())
            CHECK(out.find("- `" + std::string(t.name) + "`: " + std::string(t.limits) + ".") != std::string::npos);
    }
}

TEST_CASE("ggx bench writes a CSV of every row, two PNG charts and a Markdown report that answers first; "
          "bench/check_targets.py checks the project's targets on its CSV")
{
    const ggxtest::ScratchFolder case_folder("cli");
    if (!ggxtest::skip_unless(ggxtest::plotting_python_present(), ggxtest::plotting_python_reason))
        return;
    fs::path dir = scratch() / "bench";
    fs::create_directories(dir);
    Run run = ggx("bench --methods caps,heitz --precisions precise --jobs write,furnace,world -n 2^16 "
                  "--native-count 2^14 --repeats 5 --scene 2 --cell-samples 2^10 --no-startup --csv " +
                  (dir / "b.csv").string() + " --charts " + (dir / "b").string() + " --markdown " +
                  (dir / "B.md").string());
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::string csv = read_all(dir / "b.csv");
    CHECK(csv.rfind("method,precision,job,ns_median", 0) == 0);
    int device_rows = 0, native_rows = 0, ceiling_rows = 0, sobol_rows = 0, measured_rmse = 0;
    for (const ggxtest::BenchCsvRow& row : ggxtest::bench_csv_rows(csv)) {
        CAPTURE(row.line);
        CHECK(row.ns_median > 0.0);
        const bool sobol = row.line.find(",sobol,") != std::string::npos;
        device_rows += row.precision == "precise" && !sobol;
        sobol_rows += sobol;
        measured_rmse += row.job == "furnace" && !csv_cell(csv, row.line, "rmse_measured").empty();
        native_rows += row.precision == "native";
        ceiling_rows += row.precision == "native-vectorized";
    }
    CHECK(device_rows == 6);  // 2 methods x 3 jobs
    CHECK(sobol_rows == 4);   // 2 methods x write and furnace in precise mode
    CHECK(measured_rmse == 4);  // precise furnace rows, philox and sobol
    CHECK(native_rows == 6);
    CHECK(ceiling_rows == 1);
    std::string md = read_all(dir / "B.md");
    for (const char* part : {"## Which sampler on this device", "- **Fastest**: ", "- **Most accurate**: ",
                             "- **Lowest error at equal time**: ", "## Speed (ns per sample)", "b-speed-error.png",
                             "b-speed-rmse.png", "| caps | precise |", "| heitz | native |",
                             "ggx bench --methods caps,heitz", "## Sequences", "| caps | sobol |",
                             " M samples/s |"})
        CHECK(md.find(part) != std::string::npos);
    CHECK(md.find("device's limits") == std::string::npos);  // the project's question: ggx-limits (bench/limits)
    CHECK(md.find("## Which sampler") < md.find("## Speed (ns per sample)"));  // the user's answer first
    CHECK(md.find("Targets") == std::string::npos);  // the project's targets are bench/check_targets.py's
    CHECK(md.find("e+0") == std::string::npos);      // numbers for people, not 7.87954e+07
    // The project's targets from the same CSV, written into a copy of the report.
    Run targets = ggxtest::run_ggx("python3 " + ggxtest::check_targets_script() + " " + (dir / "b.csv").string() +
                                       " --into " + (dir / "B.md").string() + " > " + (dir / "targets.md").string(),
                                   dir / "targets.err", false);
    CAPTURE(targets.err);
    REQUIRE(targets.status == 0);
    const std::string with_targets = read_all(dir / "B.md");
    for (const char* target : {"caps / heitz speed >= 1.35, write", "every method >= 12x the native C++ baseline"}) {
        CAPTURE(target);
        CHECK(with_targets.find(target) != std::string::npos);
        CHECK(with_targets.find(target) > with_targets.find("## The project's speed targets"));
    }
    CHECK(with_targets.rfind(md, 0) == 0);  // the report kept as it was, the section after it
    CHECK(md.find("Rough dielectric") == std::string::npos);  // without --eta, conductors only
    for (const ggxtest::BenchCsvRow& row : ggxtest::bench_csv_rows(csv)) {
        CAPTURE(row.line);
        CHECK(csv_cell(csv, row.line, "eta") == "0");
        CHECK(row.job != "write-o");
    }
    for (const char* png : {"b-speed-error.png", "b-speed-rmse.png"})
        CHECK(read_all(dir / png).substr(1, 3) == "PNG");
    fs::remove_all(dir);
}

TEST_CASE("ggx merge refuses a damaged shard: a sidecar without its fields, a .npy shorter than its shape or of "
          "other columns")
{
    const ggxtest::ScratchFolder case_folder("cli");
    fs::path dir = scratch() / "damaged";
    fs::create_directories(dir);
    for (const char* name : {"a", "b"})
        REQUIRE(ggx("sample --method caps -n 100 --first " + std::string(name[0] == 'a' ? "0" : "100") + " --out " +
                    (dir / (std::string(name) + ".npy")).string())
                    .status == 0);
    const std::string merge = "merge --out " + (dir / "m.npy").string() + " " + (dir / "a.npy").string() + " " +
                              (dir / "b.npy").string();
    std::string sidecar = read_all(dir / "b.json");
    std::ofstream(dir / "b.json") << "{\"first\": \"100\"}";
    Run run = ggx(merge);
    CAPTURE(run.err);
    CHECK(run.status == 2);
    CHECK(run.err.find("SHARD") != std::string::npos);
    std::ofstream(dir / "b.json") << sidecar;
    std::string npy = read_all(dir / "b.npy");
    std::size_t at = npy.find("(100,");
    REQUIRE(at != std::string::npos);
    npy.replace(at, 5, "(900,");  // the shape now claims more rows than the bytes hold
    std::ofstream(dir / "b.npy", std::ios::binary) << npy;
    run = ggx(merge);
    CAPTURE(run.err);
    CHECK(run.status == 1);
    CHECK(run.err.find("shorter than its shape says") != std::string::npos);
    CHECK(!fs::exists(dir / "m.npy"));
    // b.npy replaced by a .npy of 1 column (weight) beside b.json's 9.
    REQUIRE(ggx("sample --method caps -n 100 --first 100 --fields weight --out " + (dir / "w.npy").string()).status == 0);
    fs::copy_file(dir / "w.npy", dir / "b.npy", fs::copy_options::overwrite_existing);
    run = ggx(merge);
    CAPTURE(run.err);
    CHECK(run.status == 2);
    CHECK(run.err.find("columns") != std::string::npos);
    CHECK(!fs::exists(dir / "m.npy"));
    fs::remove_all(dir);
}

TEST_CASE("ggx sample writes .csv with a header and .ply point clouds")
{
    const ggxtest::ScratchFolder case_folder("cli");
    fs::path csv = scratch() / "c.csv", ply = scratch() / "c.ply";
    REQUIRE(ggx("sample --method caps -n 300 --fields o,pdf_o --out " + csv.string()).status == 0);
    std::istringstream lines(read_all(csv));
    std::string line;
    std::getline(lines, line);
    CHECK(line == "o_x,o_y,o_z,pdf_o");
    std::size_t rows = 0, bad = 0;
    while (std::getline(lines, line)) {
        double x, y, z, pdf;
        char c1, c2, c3;
        std::istringstream row(line);
        row >> x >> c1 >> y >> c2 >> z >> c3 >> pdf;
        bad += !row || std::fabs(std::sqrt(x * x + y * y + z * z) - 1.0) > 1e-5 || !(pdf > 0);
        ++rows;
    }
    CHECK(rows == 300);
    CHECK(bad == 0);

    REQUIRE(ggx("sample --method heitz -n 500 --fields m --out " + ply.string()).status == 0);
    std::string bytes = read_all(ply);
    std::size_t end = bytes.find("end_header\n");
    REQUIRE(end != std::string::npos);
    CHECK(bytes.find("element vertex 500") != std::string::npos);
    CHECK(bytes.size() == end + 11 + 500 * 15);  // 3 floats and 3 color bytes per vertex
    std::size_t off_sphere = 0;
    for (std::size_t j = 0; j < 500; ++j) {
        float v[3];
        std::memcpy(v, bytes.data() + end + 11 + 15 * j, 12);
        off_sphere += std::fabs(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1.0f) > 1e-5f || v[2] <= 0.0f;
    }
    CHECK(off_sphere == 0);
    for (const fs::path& p : {csv, ply, scratch() / "c.json"})
        fs::remove(p);
}

TEST_CASE("a job split across devices writes the same bytes as one device")
{
    const ggxtest::ScratchFolder case_folder("cli");
    fs::path one = scratch() / "one.npy", split = scratch() / "split.npy";
    const std::string common = "sample --method caps-iso --alpha 0.4 --normal 0.2,0.1,1 --theta 40 -n 2500000 --seed 9 ";
    REQUIRE(ggx(common + "--out " + one.string()).status == 0);
    // Three contexts on the device the suite runs on (GGXCL_DEVICE, else the first).
    const char* selected = std::getenv("GGXCL_DEVICE");
    const std::string device = selected && *selected ? selected : "0";
    REQUIRE(device.find(',') == std::string::npos);
    REQUIRE(ggx(common + "--devices " + device + "," + device + "," + device + " --out " + split.string()).status == 0);
    CHECK(read_all(one) == read_all(split));
    for (const char* name : {"one.npy", "one.json", "split.npy", "split.json"})
        fs::remove(scratch() / name);
}

TEST_CASE("shards with consecutive --first ranges merge to exactly the one-run file")
{
    const ggxtest::ScratchFolder case_folder("cli");
    for (const std::string ext : {".npy", ".csv"}) {
        fs::path a = scratch() / ("a" + ext), b = scratch() / ("b" + ext), whole = scratch() / ("w" + ext),
                 merged = scratch() / ("m" + ext);
        const std::string common = "sample --method bounded --alpha 0.3,0.1 --theta 75 --seed 42 ";
        REQUIRE(ggx(common + "--first 0 -n 1234 --out " + a.string()).status == 0);
        REQUIRE(ggx(common + "--first 1234 -n 2000 --out " + b.string()).status == 0);
        REQUIRE(ggx(common + "--first 0 -n 3234 --out " + whole.string()).status == 0);
        REQUIRE(ggx("merge --out " + merged.string() + " " + a.string() + " " + b.string()).status == 0);
        CAPTURE(ext);
        CHECK(read_all(merged) == read_all(whole));
        CHECK(read_all(scratch() / "m.json") == read_all(scratch() / "w.json"));
        Run wrong_order = ggx("merge --out " + (scratch() / ("x" + ext)).string() + " " + b.string() + " " + a.string());
        CHECK(wrong_order.status == 2);
        CHECK(wrong_order.err.find("--first") != std::string::npos);
        for (const char* name : {"a", "b", "w", "m"}) {
            fs::remove(scratch() / (std::string(name) + ext));
            fs::remove(scratch() / (std::string(name) + ".json"));
        }
    }
}

TEST_CASE("ggx merge --manifest lists the shards in order, checked like a merge, and copies nothing")
{
    const ggxtest::ScratchFolder case_folder("cli");
    fs::path dir = scratch() / "manifest";
    fs::create_directories(dir / "parts");
    const std::string common = "sample --method caps --alpha 0.2 --theta 70 --seed 3 -n 5000 ";
    for (const char* shard : {"0/3", "1/3", "2/3"})
        REQUIRE(ggx(common + "--shard " + shard + " --out " + (dir / "parts" / "c-{shard}.npy").string()).status == 0);
    REQUIRE(ggx(common + "--out " + (dir / "one.npy").string()).status == 0);
    const std::string parts = (dir / "parts" / "c-0000.npy").string() + " " + (dir / "parts" / "c-0001.npy").string() +
                              " " + (dir / "parts" / "c-0002.npy").string();
    REQUIRE(ggx("merge --manifest " + (dir / "all.json").string() + " " + parts).status == 0);
    nlohmann::json manifest = nlohmann::json::parse(read_all(dir / "all.json"));
    nlohmann::json one = nlohmann::json::parse(read_all(dir / "one.json"));
    REQUIRE(manifest["shards"].size() == 3);
    std::uint64_t next = 0;
    std::vector<float> rows;
    for (const nlohmann::json& part : manifest["shards"]) {
        CHECK(part["first"].get<std::uint64_t>() == next);
        next += part["count"].get<std::uint64_t>();
        ggxapp::NpyArray a = ggxapp::read_npy((dir / part["file"].get<std::string>()).string());  // relative to it
        rows.insert(rows.end(), a.data.begin(), a.data.end());
    }
    CHECK(next == 5000);
    CHECK(rows == ggxapp::read_npy((dir / "one.npy").string()).data);
    manifest.erase("shards");
    one.erase("device");
    manifest.erase("device");
    CHECK(manifest == one);  // the rest is the one-run sidecar
    CHECK(!fs::exists(dir / "all.npy"));
    Run wrong_order = ggx("merge --manifest " + (dir / "x.json").string() + " " + (dir / "parts" / "c-0001.npy").string() +
                          " " + (dir / "parts" / "c-0000.npy").string());
    CHECK(wrong_order.status == 2);
    CHECK(wrong_order.err.find("--first") != std::string::npos);
    CHECK(!fs::exists(dir / "x.json"));
    Run not_json = ggx("merge --manifest " + (dir / "x.txt").string() + " " + parts);
    CHECK(not_json.status == 2);
    CHECK(not_json.err.find(".json") != std::string::npos);
    Run both = ggx("merge --manifest " + (dir / "x.json").string() + " --out " + (dir / "x.npy").string() + " " + parts);
    CHECK(both.status == 2);
    REQUIRE(ggx(common + "--shard 1/3 --out " + (dir / "parts" / "c-{shard}.csv").string()).status == 0);
    Run mixed = ggx("merge --manifest " + (dir / "x.json").string() + " " + (dir / "parts" / "c-0000.npy").string() +
                    " " + (dir / "parts" / "c-0001.csv").string());
    CHECK(mixed.status == 2);
    CHECK(mixed.err.find("one format") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("ggx bench without its native baseline still finishes and says the baseline is not available")
{
    const ggxtest::ScratchFolder case_folder("cli");
    fs::path dir = scratch() / "no-native";
    fs::create_directories(dir);
    const fs::path missing = dir / "nowhere" / "ggx-native";
    Run run = ggxtest::run_ggx("GGX_NATIVE=" + missing.string() + " " + ggxtest::ggx_binary() +
                                   " bench --methods caps --precisions precise --jobs write,furnace -n 2^12 --repeats 5 "
                                   "--no-accuracy --no-startup --csv " + (dir / "b.csv").string() + " --markdown " +
                                   (dir / "B.md").string(),
                               scratch() / "stderr.txt", false);
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    CHECK(run.err.find("native baseline not available") != std::string::npos);
    CHECK(run.err.find("GGX_NATIVE=" + missing.string()) != std::string::npos);
    std::string csv = read_all(dir / "b.csv");
    CHECK(csv.find("caps,precise,write,") != std::string::npos);
    CHECK(csv.find(",native") == std::string::npos);  // neither native rows nor the ceiling
    CHECK(read_all(dir / "B.md").find("Native C++ baseline: not available (ggx-native not found") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("ggx links no -march=native code: its baseline is the separate program ggx-native beside it")
{
    const ggxtest::ScratchFolder case_folder("cli");
    const fs::path native = fs::path(ggxtest::ggx_binary()).parent_path() / "ggx-native";
    REQUIRE(fs::is_regular_file(native));
    if (!ggxtest::skip_unless(ggxtest::program_on_path("nm"),
                              "needs nm to list ggx's symbols (apt-get install binutils)"))
        return;
    fs::path symbols = scratch() / "nm.txt";
    Run nm = ggxtest::run_ggx("{ nm -C " + ggxtest::ggx_binary() + " >" + symbols.string() + "; }",
                              scratch() / "stderr.txt", false);
    CAPTURE(nm.err);
    REQUIRE(nm.status == 0);
    std::string table = read_all(symbols);
    // A stripped ggx (the GPU check's bundle) has no table to read.
    if (!ggxtest::skip_unless(table.find("ggxapp::") != std::string::npos,
                              "needs ggx's symbol table (this ggx is stripped)"))
        return;
    CHECK(table.find("ggxnative::") == std::string::npos);  // the table is there, without the baseline
    fs::remove(symbols);
}

TEST_CASE("ggx-native prints one timing per repeat and refuses a bad argument with status 2")
{
    const ggxtest::ScratchFolder case_folder("cli");
    const std::string native = (fs::path(ggxtest::ggx_binary()).parent_path() / "ggx-native").string();
    fs::path out = scratch() / "native.txt";
    Run run = ggxtest::run_ggx("{ " + native + " time caps-iso furnace_sum 4096 2 5 0.3 0.5 0 0.866025388 >" +
                                   out.string() + "; }",
                               scratch() / "stderr.txt", false);
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    std::istringstream lines(read_all(out));
    std::string line;
    int timings = 0;
    while (std::getline(lines, line)) {
        CAPTURE(line);
        CHECK(std::stod(line) > 0.0);
        ++timings;
    }
    CHECK(timings == 5);
    Run bad = ggxtest::run_ggx(native + " time caps furnace_sum 4096 2 5 0.3 0.5 0 0.5", scratch() / "stderr.txt",
                               false);
    CHECK(bad.status == 2);
    CHECK(bad.err.find("VX VY VZ") != std::string::npos);
    fs::remove(out);
}
