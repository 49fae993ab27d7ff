// test_vectorization.cpp - on PoCL, every bulk kernel must vectorize in
// both precision modes (a kernel PoCL cannot vectorize runs about 10-20x
// slower).  Each method's sample kernel (and, in the default mode, with
// Sobol points, and its fused estimator and world-space kernels) is compiled in a child process
// with PoCL's vectorizer remarks on and a fresh kernel cache, and its
// remarks must report a vectorized work-item loop and no loop left
// unvectorized.  Negative control: a kernel calling the built-in sin, built
// the same way, is reported unvectorized.  On other OpenCL platforms the
// check does not apply and says so.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include <ggxcl/ggxcl.hpp>
#include <ggxcl/opencl.hpp>

#include "test_paths.hpp"

namespace fs = std::filesystem;

namespace {

// PoCL's remarks (printed on stdout) while a program builds its kernels: by
// default `ggx ARGUMENTS`; the negative control runs this test binary.
std::string remarks_of_run(const std::string& ggx_arguments, const fs::path& cache, const fs::path& dir,
                           const std::string& environment = "", const std::string& self_arguments = "")
{
    fs::path log = dir / "remarks.txt";
    const std::string program = self_arguments.empty() ? ggxtest::ggx_binary() + " " + ggx_arguments
                                                       : "/proc/" + std::to_string(::getpid()) + "/exe" + self_arguments;
    // GGXCL_PROGRAM_CACHE=off: a binary from an earlier run would skip the compile whose remarks are read.
    std::string command = environment + "GGXCL_PROGRAM_CACHE=off POCL_VECTORIZER_REMARKS=1 POCL_CACHE_DIR=" +
                          cache.string() + " " + program + " >" + log.string() + " 2>&1";
    int status = std::system(command.c_str());
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    const std::string output = text.str();
    // A failed run says why: its last lines (the remarks come before).
    INFO(command, "\n", output.substr(output.size() > 2000 ? output.size() - 2000 : 0));
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
    return output;
}

// The sample kernel with every field written, its uniforms from `sequence`.
std::string remarks_of(const std::string& method, const std::string& precision, const fs::path& dir,
                       const std::string& sequence = "philox")
{
    return remarks_of_run("sample --method " + method + " --precision " + precision + " --sequence " + sequence +
                              " -n 4096 --fields m,o,pdf_m,pdf_o,weight,u --out " + (dir / "v.npy").string(),
                          dir / (method + precision + sequence), dir);
}

// The fused estimator and the world-space sample kernel, through `ggx bench`.
std::string furnace_and_world_remarks(const std::string& method, const fs::path& dir)
{
    return remarks_of_run("bench --methods " + method +
                              " --precisions precise --jobs furnace,world -n 4096 --repeats 5 --no-native "
                              "--no-accuracy --no-startup",
                          dir / (method + "-bench"), dir);
}

// The negative control's kernel: the built-in sin is an out-of-line call.
std::string builtin_sin_remarks(const fs::path& dir)
{
    return remarks_of_run("", dir / "builtin-sin", dir, "GGX_VECTORIZER_PROBE=1 ", " -tc='vectorizer probe*'");
}

} // namespace

// Runs only as the negative control's child (GGX_VECTORIZER_PROBE set): builds
// and runs a kernel that calls the built-in sin, so that PoCL compiles it.
TEST_CASE("vectorizer probe: a kernel calling the built-in sin")
{
    if (std::getenv("GGX_VECTORIZER_PROBE") == nullptr)
        return;
    cl::Context context(ggxcl::select_device().device);
    cl::Device device = context.getInfo<CL_CONTEXT_DEVICES>().front();
    cl::Program program(context, "__kernel void probe(__global float* x) { size_t k = get_global_id(0); "
                                 "x[k] = sin(x[k] * 6.2831853f); }");
    program.build({device});
    cl::Buffer buffer(context, CL_MEM_READ_WRITE, 4096 * sizeof(float));
    cl::CommandQueue queue(context, device);
    cl::Kernel kernel(program, "probe");
    kernel.setArg(0, buffer);
    queue.enqueueFillBuffer(buffer, 0.25f, 0, 4096 * sizeof(float));
    queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(4096), cl::NDRange(64));
    queue.finish();
}

TEST_CASE("every bulk sample kernel vectorizes on PoCL in both precision modes")
{
    ggxcl::DeviceInfo device = ggxcl::select_device();
    if (device.platform.find("Portable Computing Language") == std::string::npos) {
        MESSAGE("not PoCL (" << device.label() << "): vectorization remarks do not apply");
        return;
    }
    fs::path dir = fs::temp_directory_path() / ("ggx-vec-test-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (const char* precision : {"precise", "relaxed"})
        for (ggxcl::Method method : ggxcl::all_methods) {
            std::string remarks = remarks_of(std::string(ggxcl::method_name(method)), precision, dir);
            CAPTURE(ggxcl::method_name(method));
            CAPTURE(precision);
            CHECK(remarks.find("vectorized loop (vectorization width") != std::string::npos);
            CHECK(remarks.find("loop not vectorized") == std::string::npos);
        }
    for (ggxcl::Method method : ggxcl::all_methods) {  // the Sobol points in the default mode
        std::string remarks = remarks_of(std::string(ggxcl::method_name(method)), "precise", dir, "sobol");
        CAPTURE(ggxcl::method_name(method));
        CHECK(remarks.find("vectorized loop (vectorization width") != std::string::npos);
        CHECK(remarks.find("loop not vectorized") == std::string::npos);
    }
    for (ggxcl::Method method : ggxcl::all_methods) {
        std::string remarks = furnace_and_world_remarks(std::string(ggxcl::method_name(method)), dir);
        CAPTURE(ggxcl::method_name(method));
        CHECK(remarks.find("vectorized loop (vectorization width") != std::string::npos);
        CHECK(remarks.find("loop not vectorized") == std::string::npos);
    }
    // Negative control: a built-in sin call blocks vectorization, and the remarks say so.
    CHECK(builtin_sin_remarks(dir).find("loop not vectorized") != std::string::npos);
    fs::remove_all(dir);
}
