// test_languages.cpp - the device headers in the five languages they are written for:
//  - every public device header of kernels/ compiles alone, without a warning, as C++17 with
//    GCC and with Clang (-Wall -Wextra -Wpedantic -Wconversion -Wdouble-promotion -Wshadow),
//    as CUDA device code (clang++ -x cuda without the CUDA toolkit, tests/cuda/cuda_shim.h
//    standing in for its headers) and as OpenCL C 1.2 (clang -x cl);
//  - tests/cuda/ggx_cuda_all.cu, which calls every sampler and pdf from __global__ functions,
//    compiles to PTX with an entry point per method of the list and no local memory;
//  - the kernel of examples/cuda compiles to PTX the same way; where nvcc is installed, the file
//    above and the whole example (host code too) compile with it;
//  - every public device header compiles alone as a GLSL 4.50 compute shader and as an HLSL one
//    (glslangValidator, the front ends shaderc uses; tests/vulkan runs them on a Vulkan device);
//  - a control: a header that calls sqrt on a float without ggx_platform.h fails the C++ check,
//    and a header with a C cast fails the GLSL check.
// Which headers count as public is tests/helpers/header_roles.hpp's rule: the kernel-only ones need
// a kernel's switches, the *_shader.h ones are GLSL and HLSL alone.
// ggx_user_sampler.h declares what a user sampler's file defines after it: it compiles
// with the test samplers of tests/user_samplers (one of whole samples, one of m alone) and the
// worked example of examples/user_sampler after it.
// The compilers and folders are CMake's, each overridable by the environment (test_paths.hpp);
// each case works in a folder of its own.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "scratch.hpp"
#include "header_roles.hpp"
#include "test_paths.hpp"

namespace {

namespace fs = std::filesystem;

struct Result {
    int status;
    std::string output;
};

// Runs a shell command, stdout and stderr together.
Result run(const std::string& command)
{
    Result r{-1, ""};
    std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe)
        return r;
    std::array<char, 4096> buffer{};
    std::size_t n;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        r.output.append(buffer.data(), n);
    r.status = ::pclose(pipe);
    return r;
}

std::vector<std::string> public_headers()
{
    std::vector<std::string> names;
    for (const fs::directory_entry& e : fs::directory_iterator(ggxtest::kernel_dir()))
        if (e.path().extension() == ".h" && !ggxtest::is_kernel_only_header(e.path().filename().string()) &&
            !ggxtest::is_shader_only_header(e.path().filename().string()))
            names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

const std::string cxx_warnings = " -Wall -Wextra -Wpedantic -Wconversion -Wdouble-promotion -Wshadow -Werror";
const std::string kernels = " -I" + ggxtest::kernel_dir();

// The commands that compile `source` (a file) in each language.
std::string gcc_cxx(const std::string& source)
{
    return ggxtest::gxx() + " -std=c++17 -fsyntax-only" + cxx_warnings + kernels + " -x c++ " + source;
}
std::string clang_cxx(const std::string& source)
{
    return ggxtest::clangxx() + " -std=c++17 -fsyntax-only" + cxx_warnings + kernels + " -x c++ " + source;
}
std::string clang_cuda(const std::string& source, const std::string& output = "")
{
    return ggxtest::clangxx() + " -x cuda --cuda-device-only -nocudainc -nocudalib --cuda-gpu-arch=sm_80" +
           " -Wno-unknown-cuda-version -Wall -Wextra -Werror -O2 -include cuda_shim.h -I" + ggxtest::cuda_dir() +
           kernels +
           (output.empty() ? " -fsyntax-only " : " -S -o " + output + " ") + source;
}
std::string clang_opencl(const std::string& source)
{
    return ggxtest::clang() + " -x cl -cl-std=CL1.2 -Xclang -finclude-default-header -fsyntax-only -Wall" +
           " -Werror" + kernels + " " + source;
}

// glslang's GLSL 4.50 (Vulkan) and HLSL front ends; -o /dev/null: the SPIR-V is made, then dropped.
std::string glslang_glsl(const std::string& source)
{
    return ggxtest::glslang_validator() + " --quiet -V" + kernels + " -o /dev/null " + source;
}
std::string glslang_hlsl(const std::string& source)
{
    return ggxtest::glslang_validator() + " --quiet -V -D -e main -S comp --target-env vulkan1.1 -DGGX_HLSL=1" + kernels +
           " -o /dev/null " + source;
}

fs::path write_file(const fs::path& path, const std::string& text)
{
    std::ofstream(path) << text;
    return path;
}

void check_compiles(const std::string& what, const std::string& command)
{
    const Result r = run(command);
    INFO(what, ": ", command, "\n", r.output);
    CHECK(r.status == 0);
    CHECK(r.output.empty());  // no warning either
}

// `source` (the text of a file) compiles in each language: written as stem.cpp, .cu and .cl.
void check_compiles_everywhere(const fs::path& stem, const std::string& source)
{
    const std::string cpp = write_file(stem.string() + ".cpp", source).string();
    const std::string cu = write_file(stem.string() + ".cu", source).string();
    const std::string cl = write_file(stem.string() + ".cl", source).string();
    check_compiles("g++", gcc_cxx(cpp));
    check_compiles("clang++", clang_cxx(cpp));
    check_compiles("clang++ -x cuda", clang_cuda(cu));
    check_compiles("clang -x cl", clang_opencl(cl));
}

std::vector<std::string> entries_of(const std::string& ptx)
{
    std::vector<std::string> names;
    std::istringstream lines(ptx);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t at = line.find(".entry ");
        if (at != std::string::npos)
            names.push_back(line.substr(at + 7, line.find('(') - at - 7));
    }
    return names;
}

std::string identifier_of(ggxcl::Method method)
{
    std::string name(ggxcl::method_name(method));
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

} // namespace

TEST_CASE("the compilers are installed (scripts/install-deps.sh: clang-15)")
{
    for (const std::string path : {ggxtest::clangxx(), ggxtest::clang()}) {
        INFO("clang-15 not found (", path, "): apt-get install clang-15");
        CHECK(path.find("NOTFOUND") == std::string::npos);
    }
}

TEST_CASE("every public device header compiles alone as C++17 (GCC, Clang), CUDA and OpenCL C 1.2")
{
    const ggxtest::ScratchFolder dir("languages");
    const std::vector<std::string> headers = public_headers();
    REQUIRE(headers.size() >= 15);
    for (const std::string& header : headers) {
        CAPTURE(header);
        const std::string include = "#include \"" + header + "\"\n";
        if (header == "ggx_user_sampler.h")
            continue;  // below, with a sampler file after it
        check_compiles_everywhere(dir / header, include);
    }
}

TEST_CASE("a user sampler's file after ggx_user_sampler.h compiles as C++17, CUDA and OpenCL C 1.2")
{
    const ggxtest::ScratchFolder dir("languages");
    const std::string tests = ggxtest::user_samplers_dir() + "/";
    for (const std::string path : {tests + "caps_copy.h", tests + "heitz_normal_only.h",
                                   ggxtest::examples_dir() + "/user_sampler/caps_native_sincos.h"}) {
        CAPTURE(path);
        const std::string file = fs::path(path).filename().string();
        const std::string samples_m = file == "heitz_normal_only.h" ? "1" : "0";
        const std::string include = "#define GGX_USER_SAMPLER 1\n#define GGX_USER_SAMPLES_M " + samples_m +
                                    "\n#include \"ggx_samplers.h\"\n#include \"" + path + "\"\n";
        check_compiles_everywhere(dir / file, include);
    }
}

TEST_CASE("control: float math outside ggx_platform.h, promoted to double, fails the C++ check")
{
    const ggxtest::ScratchFolder dir("languages");
    const std::string bad = write_file(dir / "promotes.cpp", "#include <cmath>\n"
                                                             "inline float half_length(float x) { return sqrt(x) / 2; }\n")
                                .string();
    CHECK(run(gcc_cxx(bad)).status != 0);
    CHECK(run(clang_cxx(bad)).status != 0);
}

TEST_CASE("every sampler and pdf called from CUDA: PTX with an entry point per method and no local memory")
{
    const ggxtest::ScratchFolder dir("languages");
    const std::string ptx_path = (dir / "ggx_cuda_all.ptx").string();
    const std::string source = ggxtest::cuda_dir() + "/ggx_cuda_all.cu";
    check_compiles("clang++ -x cuda -S", clang_cuda(source, ptx_path));
    const std::string ptx = ggxtest::read_all(ptx_path);
    const std::vector<std::string> entries = entries_of(ptx);
    for (ggxcl::Method method : ggxcl::all_methods) {
        CAPTURE(ggxcl::method_name(method));
        for (const std::string kind : {"sample", "pdf", "world"})
            CHECK(std::count(entries.begin(), entries.end(), "ggx_cuda_" + kind + "_" + identifier_of(method)) == 1);
    }
    CHECK(std::count(entries.begin(), entries.end(), "ggx_cuda_sobol") == 1);
    CHECK(entries.size() == 3 * ggxcl::all_methods.size() + 1);
    CHECK(ptx.find(".local") == std::string::npos);  // nothing spilled to local memory
    CHECK(ptx.find("__local_depot") == std::string::npos);
    CHECK(ptx.find("call.uni") == std::string::npos);  // every device function inlined, no libdevice call
}

TEST_CASE("every public device header compiles alone as GLSL 4.50 and as HLSL (glslangValidator)")
{
    {
        INFO("glslangValidator not found (", ggxtest::glslang_validator(), "): apt-get install glslang-tools");
        REQUIRE(ggxtest::glslang_validator().find("NOTFOUND") == std::string::npos);
    }
    const ggxtest::ScratchFolder dir("languages");
    for (const std::string& header : public_headers()) {
        CAPTURE(header);
        const std::string include = "#include \"" + header + "\"\n";
        check_compiles("GLSL", glslang_glsl(write_file(dir / (header + ".comp"),
                                                       "#version 450\n#extension GL_GOOGLE_include_directive : require\n" +
                                                           include + "layout(local_size_x = 1) in;\nvoid main() {}\n")
                                                .string()));
        check_compiles("HLSL", glslang_hlsl(write_file(dir / (header + ".hlsl"),
                                                       include + "[numthreads(1, 1, 1)]\nvoid main() {}\n")
                                                .string()));
    }
}

TEST_CASE("control: a C cast in a device function fails the GLSL check")
{
    const ggxtest::ScratchFolder dir("languages");
    const std::string bad = write_file(dir / "cast.comp", "#version 450\n#extension GL_GOOGLE_include_directive : require\n"
                                                          "#include \"ggx_common.h\"\n"
                                                          "int whole(float x) { return (int)x; }\n"
                                                          "layout(local_size_x = 1) in;\nvoid main() {}\n")
                                .string();
    CHECK(run(glslang_glsl(bad)).status != 0);
}

TEST_CASE("the CUDA example's kernel compiles to PTX with clang alone")
{
    const ggxtest::ScratchFolder dir("languages");
    const std::string unit = write_file(dir / "example.cu", "#include \"ggx_cuda_furnace.cuh\"\n").string();
    const std::string ptx_path = (dir / "example.ptx").string();
    check_compiles("clang++ -x cuda -S (example)",
                   clang_cuda("-I" + ggxtest::examples_dir() + "/cuda " + unit, ptx_path));
    const std::vector<std::string> entries = entries_of(ggxtest::read_all(ptx_path));
    REQUIRE(entries.size() == 1);
    CHECK(entries[0].find("ggx_furnace_kernel") != std::string::npos);
}

TEST_CASE("with nvcc, where installed: the same file and examples/cuda compile without a warning")
{
    if (ggxtest::nvcc().empty() || ggxtest::nvcc().find("NOTFOUND") != std::string::npos) {
        MESSAGE("nvcc not found: the clang CUDA checks above stand for it");
        return;
    }
    const ggxtest::ScratchFolder dir("languages");
    const std::string nvcc = ggxtest::nvcc() + " -std=c++17 -arch=sm_80 -Werror all-warnings" + kernels;
    check_compiles("nvcc -ptx", nvcc + " -ptx -o " + (dir / "nvcc.ptx").string() + " " + ggxtest::cuda_dir() +
                                    "/ggx_cuda_all.cu");
    check_compiles("nvcc example", nvcc + " -o " + (dir / "cuda_sample").string() + " " + ggxtest::examples_dir() +
                                       "/cuda/cuda_sample.cu");
}
