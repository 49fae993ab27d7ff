// test_vulkan_user_sampler_cli.cpp - `ggx` with user samplers in GLSL and
// HLSL (--sampler FILE.glsl|.hlsl, which implies --api vulkan; lavapipe in CI):
//   - sample: a GLSL copy of caps writes the Vulkan caps' samples;
//   - histogram: the GLSL copy and an HLSL sampler of m alone pass every
//     check; the engine-style HLSL port of examples/user_sampler
//     passes, and its copy whose pdf drops G1 fails the integral (by 1/G1) and
//     the claimed VNDF's pdf, exit 1;
//   - errors: a shader that does not compile exits 1 naming its file and
//     line; a file without its pdf, --api opencl with a shader file and a
//     --shader-language against its extension exit 2 naming the flag;
//   - stress maps the GLSL copy as caps, and the page names each file with
//     the language it was read in.
// What --sampler does on either API (the OpenCL C files, read as HLSL on
// Vulkan: negative controls, bench, converge, demo) is test_user_sampler_cli's.
#include <doctest/doctest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "cli_reports.hpp"
#include "cli_runner.hpp"
#include "histogram_verdicts.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path& scratch()
{
    return ggxtest::ScratchFolder::current();
}

using ggxtest::user_sampler_file;

std::string example_file(const std::string& name)
{
    return ggxtest::examples_dir() + "/user_sampler/engine_hlsl/" + name;
}

using ggxtest::ggx;

// `ggx histogram` of `sampler_args` at alpha 0.5 x 0.2 under --check 1e-3: its exit status and verdicts.
std::pair<int, std::map<std::string, ggxtest::HistogramVerdict>> histogram(const std::string& sampler_args,
                                                                           const std::string& config = "--alpha 0.5,0.2")
{
    const fs::path prefix = scratch() / "histogram";
    const ggxtest::Run run =
        ggx("histogram " + sampler_args + " " + config + " -n 4e5 --check 1e-3 --no-png --out " + prefix.string());
    INFO(run.err);
    return {run.status, ggxtest::histogram_verdicts(prefix)};
}

} // namespace

TEST_CASE("ggx sample --sampler FILE.glsl: the Vulkan caps' samples, on Vulkan without --api")
{
    const ggxtest::ScratchFolder case_folder("vk-user-cli");
    const fs::path mine = scratch() / "mine.npy", caps = scratch() / "caps.npy";
    const std::string common = " --alpha 0.2,0.5 --theta 75 --sequence sobol -n 3000 --fields m,o,pdf_o,weight,u ";
    REQUIRE(ggx("sample --sampler " + user_sampler_file("shaders/caps_copy.glsl") + common + "--out " + mine.string())
                .status == 0);
    REQUIRE(ggx("sample --api vulkan --method caps" + common + "--out " + caps.string()).status == 0);
    CHECK(ggxtest::read_all(mine) == ggxtest::read_all(caps));
    const std::string sidecar = ggxtest::read_all(scratch() / "mine.json");
    CHECK(sidecar.find("\"caps_copy\"") != std::string::npos);
    CHECK(sidecar.find("vulkan (glsl)") != std::string::npos);
}

TEST_CASE("ggx histogram --sampler FILE.glsl|.hlsl: shader samplers pass every check")
{
    const ggxtest::ScratchFolder case_folder("vk-user-cli");
    for (const std::string file :
         {"shaders/caps_copy.glsl", "shaders/heitz_normal_only.hlsl", "shaders/direction_adapter.glsl"}) {
        CAPTURE(file);
        const auto [status, got] = histogram("--sampler " + user_sampler_file(file));
        CHECK(status == 0);
        CHECK(got.size() == ggxtest::all_user_checks("vndf").size());
        for (const auto& [name, verdict] : got) {
            CAPTURE(name);
            CHECK(verdict.passed);
        }
    }
}

TEST_CASE("the library's methods and right engine conventions, read as GLSL, pass every check on Vulkan")
{
    const ggxtest::ScratchFolder case_folder("vk-user-cli");
    for (const ggxtest::HistogramControl& row : ggxtest::harness_exact(true)) {
        CAPTURE(row.file);
        CAPTURE(row.args);
        const auto [status, got] =
            histogram("--api vulkan --shader-language glsl --sampler " + user_sampler_file(row.file), row.args);
        CHECK(status == 0);
        for (const std::string& name : row.passing)
            CHECK_MESSAGE((got.count(name) == 1 && got.at(name).passed), name);
    }
}

TEST_CASE("examples/user_sampler/engine_hlsl: the engine's port passes; the same port without G1 in its pdf fails")
{
    const ggxtest::ScratchFolder case_folder("vk-user-cli");
    for (const char* adapter : {"engine_vndf_check.hlsl", "engine_direction_check.hlsl"}) {
        CAPTURE(adapter);
        const auto [good_status, good] = histogram("--sampler " + example_file(adapter));
        CHECK(good_status == 0);
        CHECK(good.size() == ggxtest::all_user_checks("vndf").size());
        for (const auto& [name, verdict] : good)
            CHECK_MESSAGE(verdict.passed, name);
    }
    const auto [bad_status, bad] = histogram("--sampler " + example_file("engine_vndf_pdf_without_g1.hlsl"));
    CHECK(bad_status == 1);
    CHECK(bad.at("its own pdf").passed);  // a constant factor: the chi-square cannot see it
    CHECK(bad.at("the claimed vndf").passed);
    CHECK(bad.at("pdf from (i, o)").passed);
    CHECK_FALSE(bad.at("pdf of the claimed vndf").passed);
    const ggxtest::HistogramVerdict integral = bad.at("pdf integrates to 1");
    CHECK_FALSE(integral.passed);
    // 1 / G1 of the view at 60 degrees, alpha 0.5 x 0.2 (phi 0: alpha_x alone), by how much it is off.
    const double tan2 = 3.0, g1 = 2.0 / (1.0 + std::sqrt(1.0 + 0.25 * tan2));
    const double total = std::stod(integral.summary.substr(integral.summary.find(": ") + 2));
    CHECK(total == doctest::Approx(1.0 / g1).epsilon(0.01));
}

TEST_CASE("ggx --sampler FILE.glsl|.hlsl: a shader that does not compile exits 1 at its line; bad uses exit 2")
{
    const ggxtest::ScratchFolder case_folder("vk-user-cli");
    const ggxtest::Run broken = ggx("sample --sampler " + user_sampler_file("shaders/undeclared_name.hlsl") +
                                    " -n 10 --out " + (scratch() / "broken.npy").string());
    CHECK(broken.status == 1);
    CHECK(broken.err.find("undeclared_name.hlsl:9:") != std::string::npos);
    CHECK_FALSE(fs::exists(scratch() / "broken.npy"));
    const std::string glsl = user_sampler_file("shaders/caps_copy.glsl");
    const std::string out = " --out " + (scratch() / "bad").string();
    const std::pair<std::string, std::string> bad[] = {
        {"sample -n 10 --sampler " + user_sampler_file("shaders/no_pdf.glsl") + out, "ggx_user_pdf"},
        {"sample -n 10 --api opencl --sampler " + glsl + out, "--api"},
        {"histogram -n 10 --shader-language hlsl --sampler " + glsl + out, "--shader-language"},
        {"stress --api opencl --sampler " + glsl + out, "--api"},
        {"bench --api opencl --sampler " + glsl, "--api"},
        {"converge --api opencl --sampler " + glsl, "--api"},
        {"demo --api opencl --sampler " + glsl + out, "--api"},
    };
    for (const auto& [args, named] : bad) {
        CAPTURE(args);
        const ggxtest::Run run = ggx(args);
        CHECK(run.status == 2);
        CHECK(run.err.find(named) != std::string::npos);
    }
}

TEST_CASE("ggx stress with a GLSL copy of caps: caps' map; NaN where the OpenCL C control, read as GLSL, divides by "
          "zero; the page names each file's language")
{
    const ggxtest::ScratchFolder case_folder("vk-user-cli");
    const std::string copy = user_sampler_file("shaders/caps_copy.glsl");
    const fs::path prefix = scratch() / "stress";
    const fs::path page = scratch() / "stress.html";
    const ggxtest::Run run = ggx("stress --methods caps --sampler " + copy + " --sampler " +
                                 user_sampler_file("divides_by_zero.h") + " --no-png --out " + prefix.string() +
                                 " --html " + page.string());
    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    const std::string csv = ggxtest::read_all(prefix.string() + ".csv");
    auto [rows, nan_inf] = ggxtest::stress_rows(csv);
    CHECK(rows["caps_copy device"] == rows["caps device"]);
    CHECK(nan_inf["caps_copy device"] == 0);
    CHECK(nan_inf["divides_by_zero device"] > 0);
    const std::string html = ggxtest::read_all(page);  // each file named with the language it was read in
    CHECK(html.find("caps_copy.glsl</code>, GLSL") != std::string::npos);
    CHECK(html.find("divides_by_zero.h</code>, GLSL") != std::string::npos);
}
