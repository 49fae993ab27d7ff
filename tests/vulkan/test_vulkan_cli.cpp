// test_vulkan_cli.cpp - `ggx` on Vulkan end to end:
//   - `ggx devices` lists the Vulkan device with its vulkan: selector beside
//     the OpenCL devices, and `--api vulkan` lists it alone;
//   - `ggx sample --api vulkan` (GLSL and HLSL, conductor and dielectric, and
//     --device vulkan:NAME) writes the samples OpenCL writes for the same
//     request within the shader bounds (m and o 99% <= 1e-5 rad, max <= 2e-3;
//     pdf_o relative 99% <= 1e-4), the uniforms bit for bit, and a sidecar
//     that names the API and the device;
//   - shards on Vulkan join to the whole job bit for bit;
//   - `ggx bench --api opencl,vulkan` (GLSL and HLSL) times the write and
//     furnace jobs on both APIs in one run, on philox and Sobol, each row with
//     its api, and the ratio table; `--api vulkan` alone times Vulkan alone,
//     every job, with charts, a page and the dielectric's accuracy; an
//     unknown API in the list is a usage error;
//   - `ggx stress --api vulkan` writes the map (CSV, page naming the Vulkan
//     device), conductor and dielectric, GLSL and HLSL;
//   - `ggx converge --api vulkan` (HLSL) writes OpenCL's curves within float
//     rounding; `ggx demo --api vulkan` writes every method's files and a
//     summary naming the API;
//   - usage errors (exit 2, naming the flag): --shader-language without
//     Vulkan, --api opencl with a vulkan: device, --devices with Vulkan,
//     --sampler with Vulkan, an unknown API;
//   - no Vulkan driver (VK_ICD_FILENAMES naming nothing): exit 1 and a message
//     that says what to install.
// `ggx histogram` and `ggx --sampler` on Vulkan are test_histogram_cli's and
// test_user_sampler_cli's, written once for both APIs (cli_api.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include <ggxcl/ggxcl.hpp>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "npy_file.hpp"

namespace {

namespace fs = std::filesystem;

std::string ggx_out(const std::string& args, const fs::path& scratch)
{
    const std::string command = ggxtest::ggx_binary() + " " + args + " >" + (scratch / "out.txt").string() + " 2>&1";
    CHECK(std::system(command.c_str()) == 0);
    return ggxtest::read_all(scratch / "out.txt");
}

ggxcl::Vec3 row_vector(const ggxapp::NpyArray& a, std::uint64_t row, int column)
{
    const float* r = a.data.data() + row * a.columns + column;
    return {r[0], r[1], r[2]};
}

double angle(const ggxcl::Vec3& a, const ggxcl::Vec3& b)
{
    const double cx = double(a.y) * b.z - double(a.z) * b.y, cy = double(a.z) * b.x - double(a.x) * b.z,
                 cz = double(a.x) * b.y - double(a.y) * b.x;
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z);
}

// Columns m (3), o (3), pdf_o, u (2 or 3) of two files of the same request.
void check_same_samples(const fs::path& vulkan_file, const fs::path& opencl_file, const std::string& label)
{
    const ggxapp::NpyArray v = ggxapp::read_npy(vulkan_file.string()), c = ggxapp::read_npy(opencl_file.string());
    REQUIRE(v.rows == c.rows);
    REQUIRE(v.columns == c.columns);
    std::vector<double> angles, pdfs;
    bool same_u = true;
    for (std::uint64_t j = 0; j < v.rows; ++j) {
        angles.push_back(angle(row_vector(v, j, 0), row_vector(c, j, 0)));
        angles.push_back(angle(row_vector(v, j, 3), row_vector(c, j, 3)));
        const double p = v.data[j * v.columns + 6], q = c.data[j * c.columns + 6];
        pdfs.push_back(std::abs(p - q) / std::max(std::abs(q), 1e-30));
        for (std::uint64_t k = 7; k < v.columns; ++k)
            same_u = same_u && v.data[j * v.columns + k] == c.data[j * c.columns + k];
    }
    std::sort(angles.begin(), angles.end());
    std::sort(pdfs.begin(), pdfs.end());
    INFO(label, ": angle 99% ", angles[angles.size() * 99 / 100], ", max ", angles.back(), "; pdf_o relative 99% ",
         pdfs[pdfs.size() * 99 / 100]);
    CHECK(angles[angles.size() * 99 / 100] <= 1e-5);
    CHECK(angles.back() <= 2e-3);
    CHECK(pdfs[pdfs.size() * 99 / 100] <= 1e-4);
    CHECK(same_u);
}

} // namespace

TEST_CASE("ggx devices lists the Vulkan device with its selector")
{
    const ggxtest::ScratchFolder scratch("vulkan-cli");
    const std::string all = ggx_out("devices", scratch.path());
    CHECK(all.find("0: ") == 0);  // OpenCL first
    CHECK(all.find("vulkan:0: llvmpipe") != std::string::npos);
    CHECK(all.find("select with --device vulkan:0") != std::string::npos);
    CHECK(all.find("storage buffers up to 128 MiB") != std::string::npos);
    const std::string vulkan = ggx_out("devices --api vulkan", scratch.path());
    CHECK(vulkan.find("vulkan:0: llvmpipe") == 0);
}

TEST_CASE("ggx sample --api vulkan writes OpenCL's samples, GLSL and HLSL, conductor and dielectric")
{
    const ggxtest::ScratchFolder scratch("vulkan-cli");
    const std::string fields = " --fields m,o,pdf_o,u -n 50000 --seed 9 --first 77 ";
    for (const std::string request : {"--method bounded --alpha 0.2,0.6 --theta 75",
                                      "--method caps --alpha 0.3 --theta 40 --eta 1.5",
                                      "--method heitz --alpha 0.1,0.4 --theta 130 --eta 1.33 --transport importance"}) {
        const fs::path opencl = scratch / "opencl.npy";
        REQUIRE(ggxtest::run_ggx("sample " + request + fields + "--out " + opencl.string(), scratch / "err.txt").status == 0);
        for (const std::string api : {"--api vulkan", "--api vulkan --shader-language hlsl", "--device vulkan:llvmpipe"}) {
            const fs::path vulkan = scratch / "vulkan.npy";
            const ggxtest::Run run = ggxtest::run_ggx("sample " + request + fields + api + " --out " + vulkan.string(),
                                                      scratch / "err.txt");
            REQUIRE_MESSAGE(run.status == 0, run.err);
            check_same_samples(vulkan, opencl, request + " " + api);
            const nlohmann::json sidecar = nlohmann::json::parse(ggxtest::read_all(scratch / "vulkan.json"));
            CHECK(sidecar["api"] == (api.find("hlsl") != std::string::npos ? "vulkan (hlsl)" : "vulkan (glsl)"));
            CHECK(sidecar["device"].get<std::string>().rfind("vulkan:llvmpipe", 0) == 0);
        }
    }
}

TEST_CASE("shards on Vulkan join to the whole job bit for bit")
{
    const ggxtest::ScratchFolder scratch("vulkan-cli");
    const std::string job = "sample --api vulkan --method ndf --alpha 0.5 -n 10001 --fields o,pdf_o ";
    REQUIRE(ggxtest::run_ggx(job + "--out " + (scratch / "whole.npy").string(), scratch / "err.txt").status == 0);
    for (const char* shard : {"0/3", "1/3", "2/3"})
        REQUIRE(ggxtest::run_ggx(job + "--shard " + shard + " --out " + (scratch / "part{shard}.npy").string(),
                                 scratch / "err.txt").status == 0);
    const ggxapp::NpyArray whole = ggxapp::read_npy((scratch / "whole.npy").string());
    std::vector<float> joined;
    for (const char* part : {"part0000.npy", "part0001.npy", "part0002.npy"}) {
        const ggxapp::NpyArray a = ggxapp::read_npy((scratch / part).string());
        joined.insert(joined.end(), a.data.begin(), a.data.end());
    }
    CHECK(joined == whole.data);
}

TEST_CASE("ggx bench --api opencl,vulkan times each job on both APIs in one run, with their ratio; --api vulkan "
          "alone gets every job, charts, a page and the dielectric's accuracy")
{
    const ggxtest::ScratchFolder scratch("vulkan-cli");
    for (const std::string language : {"glsl", "hlsl"}) {
        const fs::path csv = scratch / ("bench-" + language + ".csv"), md = scratch / ("bench-" + language + ".md");
        const ggxtest::Run run = ggxtest::run_ggx("bench --api opencl,vulkan --shader-language " + language +
                                                      " -n 2^12 --repeats 5 --methods caps,ndf --precisions precise "
                                                      "--jobs write,furnace --eta 1.5 --no-accuracy --no-native "
                                                      "--no-startup --csv " + csv.string() + " --markdown " + md.string(),
                                                  scratch / "err.txt");
        CAPTURE(language);
        CAPTURE(run.err);
        REQUIRE(run.status == 0);
        const std::string text = ggxtest::read_all(csv), vulkan = "vulkan (" + language + ")";
        std::map<std::string, int> count;  // rows per api and sequence
        for (const ggxtest::BenchCsvRow& row : ggxtest::bench_csv_rows(text)) {
            CAPTURE(row.line);
            CHECK(row.ns_median > 0.0);
            ++count[ggxtest::csv_cell(text, row.line, "api") + " " + ggxtest::csv_cell(text, row.line, "sequence")];
        }
        // caps and ndf: write, its unguarded twin, furnace, the conductor's and dielectric's write-o and the
        // dielectric's furnace; OpenCL's store-only ceiling besides.
        CHECK(count["opencl philox"] == 13);
        CHECK(count[vulkan + " philox"] == 12);
        CHECK(count["opencl sobol"] == 4);  // caps and ndf: write, furnace (the conductor's)
        CHECK(count[vulkan + " sobol"] == 4);
        const std::string report = ggxtest::read_all(md);
        CHECK(report.find("# The APIs side by side") != std::string::npos);
        CHECK(report.find("| " + vulkan + " / opencl |") != std::string::npos);
        CHECK(report.find("# On vulkan:") != std::string::npos);
    }
    const fs::path csv = scratch / "alone.csv", page = scratch / "alone.html";
    const ggxtest::Run alone = ggxtest::run_ggx("bench --api vulkan -n 2^12 --repeats 5 --methods caps --precisions "
                                                "precise --sequences philox --eta 1.5 --scene 2 --cell-samples 2^10 "
                                                "--no-native --no-startup --csv " + csv.string() + " --html " +
                                                    page.string(),
                                                scratch / "err.txt");
    CAPTURE(alone.err);
    REQUIRE(alone.status == 0);
    const std::string text = ggxtest::read_all(csv);
    std::map<std::string, int> jobs;
    for (const ggxtest::BenchCsvRow& row : ggxtest::bench_csv_rows(text)) {
        CAPTURE(row.line);
        CHECK(ggxtest::csv_cell(text, row.line, "api") == "vulkan (glsl)");  // Vulkan alone
        ++jobs[row.job];
        if (row.job == "furnace" && ggxtest::csv_cell(text, row.line, "eta") != "0")  // the dielectric's accuracy
            CHECK(std::abs(std::stod(ggxtest::csv_cell(text, row.line, "reflectance")) -
                           std::stod(ggxtest::csv_cell(text, row.line, "reflectance_exact"))) <
                  6 * std::stod(ggxtest::csv_cell(text, row.line, "reflectance_se")));
    }
    for (const char* job : {"write", "furnace", "world", "per-sample", "write-o"})
        CHECK(jobs[job] > 0);
    const std::string html = ggxtest::read_all(page);
    CHECK(html.find("alone-speed-error.png") != std::string::npos);
    CHECK(fs::exists(scratch / "alone-speed-rmse.png"));
    const ggxtest::Run wrong = ggxtest::run_ggx("bench --api opencl,metal -n 2^12", scratch / "err.txt");
    CHECK(wrong.status == 2);
    CHECK(wrong.err.find("--api") != std::string::npos);
}

TEST_CASE("ggx stress --api vulkan writes the map of every method asked, conductor and dielectric")
{
    const ggxtest::ScratchFolder scratch("vulkan-cli");
    for (const std::string args : {"--methods caps,ndf", "--methods heitz --eta 1.5 --shader-language hlsl"}) {
        const ggxtest::Run run = ggxtest::run_ggx("stress --api vulkan --no-png " + args + " --out " +
                                                      (scratch / "s").string() + " --html " + (scratch / "s.html").string(),
                                                  scratch / "err.txt");
        CAPTURE(args);
        CAPTURE(run.err);
        REQUIRE(run.status == 0);
        const std::string csv = ggxtest::read_all(scratch / "s.csv");
        CHECK(csv.find("\n" + args.substr(10, 4)) != std::string::npos);  // the first method's rows
        CHECK(csv.find(",device,") != std::string::npos);
        CHECK(ggxtest::read_all(scratch / "s.html").find("vulkan:") != std::string::npos);
    }
}

TEST_CASE("ggx converge --api vulkan gives OpenCL's curves")
{
    const ggxtest::ScratchFolder scratch("vulkan-cli");
    const std::string common = "converge --methods caps,ndf --sequences philox,sobol --integrands albedo,lobe "
                               "--alphas 0.3 --thetas 45 --max-n 2^10 --randomizations 4 --speed-n 2^12 --csv ";
    std::string csv[2];
    for (int api = 0; api < 2; ++api) {
        const fs::path path = scratch / (api ? "vk.csv" : "cl.csv");
        const ggxtest::Run run =
            ggxtest::run_ggx(common + path.string() + (api ? " --api vulkan --shader-language hlsl" : ""),
                             scratch / "err.txt");
        CAPTURE(run.err);
        REQUIRE(run.status == 0);
        csv[api] = ggxtest::read_all(path);
        if (api)
            CHECK(run.err.find("vulkan (hlsl)") != std::string::npos);  // the progress line names the API
    }
    // The same rows; every number within float rounding of the samples (the last columns: rmse, mean, ...).
    std::istringstream cl_rows(csv[0]), vk_rows(csv[1]);
    std::string cl_line, vk_line;
    int rows = 0;
    while (std::getline(cl_rows, cl_line)) {
        REQUIRE(std::getline(vk_rows, vk_line));
        ++rows;
        std::istringstream a(cl_line), b(vk_line);
        for (std::string x, y; std::getline(a, x, ',') && std::getline(b, y, ',');) {
            CAPTURE(cl_line);
            CAPTURE(vk_line);
            char* end = nullptr;
            const double vx = std::strtod(x.c_str(), &end);
            if (end == x.c_str() || *end != '\0')
                CHECK(x == y);  // a name
            else
                CHECK(std::fabs(vx - std::stod(y)) <= 1e-4 * std::fabs(vx) + 1e-7);
        }
    }
    CHECK(rows > 1);
}

TEST_CASE("ggx demo --api vulkan writes every method's files and a summary naming the API")
{
    const ggxtest::ScratchFolder scratch("vulkan-cli");
    const ggxtest::Run run = ggxtest::run_ggx("demo --api vulkan --no-png --no-html -n 1000 --histogram-n 1e5 --out " +
                                                  (scratch / "demo").string(),
                                              scratch / "err.txt");
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    for (ggxcl::Method method : ggxcl::all_methods) {
        const std::string name(ggxcl::method_name(method));
        CHECK(fs::exists(scratch / "demo" / (name + ".npy")));
        CHECK(fs::exists(scratch / "demo" / (name + ".hist.json")));
    }
    CHECK(ggxtest::read_all(scratch / "demo" / "index.md").find("vulkan (glsl)") != std::string::npos);
}

TEST_CASE("usage errors with Vulkan name the flag (exit 2)")
{
    const ggxtest::ScratchFolder scratch("vulkan-cli");
    const std::string out = " -n 10 --out " + (scratch / "x.npy").string();
    struct Case {
        std::string args, flag;
    };
    for (const Case& c : {Case{"--method caps --shader-language hlsl", "--shader-language"},
                          Case{"--method caps --api opencl --device vulkan:0", "--device"},
                          Case{"--method caps --api vulkan --devices 0,0", "--devices"},
                          Case{"--method caps --api vulkan --all-devices", "--all-devices"},
                          Case{"--method caps --api metal", "--api"},
                          Case{"--method caps --api vulkan --shader-language wgsl", "--shader-language"},
                          Case{"--method caps --api vulkan --device nosuch", "--device"}}) {
        const ggxtest::Run run = ggxtest::run_ggx("sample " + c.args + out, scratch / "err.txt");
        CAPTURE(c.args);
        CAPTURE(run.err);
        CHECK(run.status == 2);
        CHECK(run.err.find(c.flag) != std::string::npos);
    }
    CHECK(!fs::exists(scratch / "x.npy"));
}

TEST_CASE("no Vulkan driver: exit 1 and what to install")
{
    const ggxtest::ScratchFolder scratch("vulkan-cli");
    const std::string no_driver = "env VK_ICD_FILENAMES=" + (scratch / "none.json").string() + " " + ggxtest::ggx_binary();
    for (const std::string& args : {std::string("devices --api vulkan"),
                                   "sample --api vulkan --method caps -n 10 --out " + (scratch / "x.npy").string()}) {
        const ggxtest::Run run = ggxtest::run_ggx(no_driver + " " + args, scratch / "err.txt", false);
        CAPTURE(args);
        CAPTURE(run.err);
        CHECK(run.status == 1);
        CHECK(run.err.find("mesa-vulkan-drivers") != std::string::npos);
    }
    CHECK(!fs::exists(scratch / "x.npy"));
}
