// test_histogram_cli.cpp - `ggx histogram` end to end, on either API
// (cli_api.hpp: CTest runs it on OpenCL and on Vulkan): the chi-square test
// passes for every method at the default configuration, its summary naming
// the API, fails for a wrong pdf (negative control, exit 1 under --check),
// and the figure decodes as a PNG of the expected size (skipped without a
// Python with matplotlib: prerequisites.hpp).  Each case works in a folder
// of its own.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <stb/stb_image.h>

#include "cli_api.hpp"
#include "cli_runner.hpp"
#include "prerequisites.hpp"
#include "skip.hpp"

namespace fs = std::filesystem;

namespace {

// The running case's own folder (each case makes one).
const fs::path& scratch()
{
    return ggxtest::ScratchFolder::current();
}

int ggx(const std::string& args)
{
    return ggxtest::ggx_on_api(args).status;
}

nlohmann::json summary(const fs::path& prefix)
{
    std::ifstream in(prefix.string() + ".json");
    return nlohmann::json::parse(in);
}

} // namespace

TEST_CASE("histogram: every method passes its own chi-square test at the default configuration")
{
    const ggxtest::ScratchFolder case_folder("hist");
    if (!ggxtest::cli_api_present())
        return;
    for (const char* method : {"ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded"}) {
        CAPTURE(method);
        fs::path prefix = scratch() / method;
        CHECK(ggx(std::string("histogram --method ") + method + " -n 1e6 --check 0.001 --no-png --out " +
                  prefix.string()) == 0);
        nlohmann::json s = summary(prefix);
        CHECK(s["count"] == 1000000);
        CHECK(s["api"] == ggxtest::cli_api().label);
        CHECK(s["dof"].get<int>() > 100);
        std::ifstream npy(prefix.string() + ".observed.npy", std::ios::binary);
        std::string head(128, '\0');
        npy.read(head.data(), 128);
        CHECK(head.find("'descr': '<f8'") != std::string::npos);
        CHECK(head.find("'shape': (32, 64)") != std::string::npos);
    }
}

TEST_CASE("histogram of m: every method passes against its pdf of m, and NDF normals fail the VNDF's")
{
    const ggxtest::ScratchFolder case_folder("hist");
    if (!ggxtest::cli_api_present())
        return;
    for (const char* method : {"ndf", "heitz", "heitz2017", "caps", "caps-iso", "bounded"}) {
        CAPTURE(method);
        fs::path prefix = scratch() / (std::string("m-") + method);
        CHECK(ggx(std::string("histogram --of m --method ") + method + " --theta 50 -n 1e6 --check 0.001 --no-png --out " +
                  prefix.string()) == 0);
        CHECK(summary(prefix)["direction"] == "m");
    }
    CHECK(ggx("histogram --of m --method ndf --against caps -n 1e6 --check 0.01 --no-png --out " +
              (scratch() / "m-wrong").string()) == 1);
}

TEST_CASE("histogram: a wrong pdf is rejected and --check turns it into exit status 1")
{
    const ggxtest::ScratchFolder case_folder("hist");
    if (!ggxtest::cli_api_present())
        return;
    fs::path prefix = scratch() / "wrong";
    CHECK(ggx("histogram --method ndf --against caps -n 1e6 --check 0.01 --no-png --out " + prefix.string()) == 1);
    CHECK(summary(prefix)["p_value"].get<double>() < 1e-6);
}

TEST_CASE("histogram: the figure decodes as a 1280 x 400 PNG")
{
    const ggxtest::ScratchFolder case_folder("hist");
    if (!ggxtest::cli_api_present() ||
        !ggxtest::skip_unless(ggxtest::plotting_python_present(), ggxtest::plotting_python_reason))
        return;
    fs::path prefix = scratch() / "figure";
    REQUIRE(ggx("histogram --method bounded --alpha 0.2,0.5 --theta 70 -n 2e5 --out " + prefix.string()) == 0);
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load((prefix.string() + ".png").c_str(), &width, &height, &channels, 0);
    REQUIRE(pixels != nullptr);
    CHECK(width == 1280);
    CHECK(height == 400);
    CHECK(channels >= 3);
    stbi_image_free(pixels);
}

TEST_CASE("histogram and sample of a rough dielectric (--eta): both lobes pass, bounded and eta 1 are refused")
{
    const ggxtest::ScratchFolder case_folder("hist");
    if (!ggxtest::cli_api_present())
        return;
    const fs::path prefix = scratch() / "glass";
    const ggxtest::Run glass = ggxtest::ggx_on_api("histogram --method heitz --eta 1.5 --theta 130 -n 4e5 --check 0.001 "
                                                   "--no-png --out " + prefix.string());
    CAPTURE(glass.err);
    CHECK(glass.status == 0);
    nlohmann::json s = summary(prefix);
    CHECK(s["eta"].get<double>() == doctest::Approx(1.5));
    CHECK(s["transport"] == "radiance");
    CHECK(s["invalid_samples"].get<std::uint64_t>() > 0);  // inside glass, reflections that leave the surface
    const fs::path wrong = scratch() / "wrong";
    CHECK(ggx("histogram --method heitz --eta 1.5 --theta 130 -n 4e5 --against ndf --check 0.001 --no-png --out " +
              wrong.string()) == 1);
    for (const char* bad : {"--eta 1", "--eta -1.5", "--eta nan", "--eta x", "--method bounded --eta 1.5"}) {
        CAPTURE(bad);
        const std::string method = std::string(bad).find("--method") == std::string::npos ? "--method caps " : "";
        const ggxtest::Run run = ggxtest::ggx_on_api("sample " + method + bad + " -n 10 --out " +
                                                     (scratch() / "bad.npy").string());
        CHECK(run.status == 2);
        CHECK(run.err.find("--eta") != std::string::npos);
        CHECK_FALSE(fs::exists(scratch() / "bad.npy"));
    }
    const fs::path cloud = scratch() / "glass.npy";
    CHECK(ggx("sample --method caps --eta 1.5 --transport importance -n 100 --fields o,u --out " + cloud.string()) ==
          0);
    std::ifstream sidecar(scratch() / "glass.json");
    const nlohmann::json doc = nlohmann::json::parse(sidecar);
    CHECK(doc["columns"] == nlohmann::json({"o_x", "o_y", "o_z", "u1", "u2", "u3"}));
    CHECK(doc["transport"] == "importance");
}
