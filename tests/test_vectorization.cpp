// test_vectorization.cpp - on PoCL, every bulk kernel must vectorize in the
// fast and relaxed modes (a kernel PoCL cannot vectorize runs about 10-20x
// slower).  Each method's sample kernel (and, in fast mode, its fused
// estimator and world-space kernels) is compiled in a child process with
// PoCL's vectorizer remarks on and a fresh kernel cache, and its remarks
// must report a vectorized work-item loop and no loop left unvectorized.
// On other OpenCL platforms the check does not apply and says so.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include <ggxcl/ggxcl.hpp>

namespace fs = std::filesystem;

namespace {

// PoCL's remarks (printed on stdout) while `ggx_arguments` builds its kernels.
std::string remarks_of_run(const std::string& ggx_arguments, const fs::path& cache, const fs::path& dir)
{
    fs::path log = dir / "remarks.txt";
    // GGXCL_PROGRAM_CACHE=off: a binary from an earlier run would skip the compile whose remarks are read.
    std::string command = "GGXCL_PROGRAM_CACHE=off POCL_VECTORIZER_REMARKS=1 POCL_CACHE_DIR=" + cache.string() + " " + GGX_BINARY + " " +
                          ggx_arguments + " >" + log.string() + " 2>&1";
    int status = std::system(command.c_str());
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The sample kernel with every field written.
std::string remarks_of(const std::string& method, const std::string& precision, const fs::path& dir)
{
    return remarks_of_run("sample --method " + method + " --precision " + precision +
                              " -n 4096 --fields m,o,pdf_m,pdf_o,weight --out " + (dir / "v.npy").string(),
                          dir / (method + precision), dir);
}

// The fused estimator and the world-space sample kernel, through `ggx bench`.
std::string furnace_and_world_remarks(const std::string& method, const fs::path& dir)
{
    return remarks_of_run("bench --methods " + method +
                              " --precisions fast --jobs furnace,world -n 4096 --repeats 5 --no-native "
                              "--no-accuracy --no-startup",
                          dir / (method + "-bench"), dir);
}

} // namespace

TEST_CASE("every bulk sample kernel vectorizes on PoCL in the fast and relaxed modes")
{
    ggxcl::DeviceInfo device = ggxcl::select_device();
    if (device.platform.find("Portable Computing Language") == std::string::npos) {
        MESSAGE("not PoCL (" << device.label() << "): vectorization remarks do not apply");
        return;
    }
    fs::path dir = fs::temp_directory_path() / ("ggx-vec-test-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (const char* precision : {"fast", "relaxed"})
        for (ggxcl::Method method : ggxcl::all_methods) {
            std::string remarks = remarks_of(std::string(ggxcl::method_name(method)), precision, dir);
            CAPTURE(ggxcl::method_name(method));
            CAPTURE(precision);
            CHECK(remarks.find("vectorized loop (vectorization width") != std::string::npos);
            CHECK(remarks.find("loop not vectorized") == std::string::npos);
        }
    for (ggxcl::Method method : ggxcl::all_methods) {
        std::string remarks = furnace_and_world_remarks(std::string(ggxcl::method_name(method)), dir);
        CAPTURE(ggxcl::method_name(method));
        CHECK(remarks.find("vectorized loop (vectorization width") != std::string::npos);
        CHECK(remarks.find("loop not vectorized") == std::string::npos);
    }
    // Negative control: the built-in sin/cos of the precise mode are calls that block vectorization.
    CHECK(remarks_of("caps", "precise", dir).find("loop not vectorized") != std::string::npos);
    fs::remove_all(dir);
}
