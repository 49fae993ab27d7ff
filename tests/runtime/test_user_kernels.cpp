// test_user_kernels.cpp - the device headers inside a user's own kernels:
// a user kernel that includes ggx_samplers.h (through
// build_user_program's -I, through headers written by write_device_headers,
// or with the embedded text prepended) reproduces Sampler::enqueue bit for
// bit; each header compiles alone and all together; every name they define
// is prefixed ggx_ / GGX_ (with a negative control on a synthetic source);
// build failures carry the log.  And a pipeline's split of one range over
// two samplers on two contexts gives the one-sampler bits.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <unistd.h>

#include "bit_compare.hpp"
#include "device_fixture.hpp"
#include "device_symbols.hpp"
#include "header_roles.hpp"
#include "user_samples.hpp"

namespace {

using ggxtest::SamplePlanes;
using ggxtest::same_bits;

// A sampler configuration and the build options a user kernel needs to
// match the runtime's program for it (with the precision mode's, added at
// the build).
struct Case {
    ggxcl::SampleParams params;
    std::string user_options;
};

std::vector<Case> cases_of_every_method()
{
    std::vector<Case> cases;
    for (ggxcl::Method method : ggxcl::all_methods) {
        ggxcl::SampleParams p{method, 0.2f, 0.45f, ggxcl::view_from_angles(63, 30)};
        if (method == ggxcl::Method::caps_iso) {
            p.alpha_y = p.alpha_x;
            cases.push_back({p, "-DGGX_NORMAL_IS_Z=1"});  // the runtime's form for n = z
            p.normal = {0.0f, 0.6f, 0.8f};
            p.view = {0.3f, -0.2f, 0.9f};
        }
        cases.push_back({p, ""});
    }
    return cases;
}

std::string label(const Case& c)
{
    return std::string(ggxcl::method_name(c.params.method)) + " " +
           std::string(ggxcl::precision_name(c.params.precision)) + " normal z " +
           std::to_string(c.params.normal.z) + " options '" + c.user_options + "'";
}

const ggxcl::SampleRange test_range{0xabcd5678ull, (1ull << 33) + 17, 3001};

} // namespace

TEST_CASE("a user kernel including ggx_samplers.h reproduces Sampler::enqueue bit for bit")
{
    auto& sampler = ggxtest::sampler();
    for (const Case& c : cases_of_every_method()) {
        INFO(label(c));
        // The precision mode's options, as the runtime builds it (none for precise on a device
        // without CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT).
        const std::string options = c.user_options + ggxcl::precision_options(sampler.device(), c.params.precision);
        cl::Program program = ggxcl::build_user_program(sampler.context(), sampler.device(),
                                                        ggxtest::user_samples_source(true), options);
        SamplePlanes mine = ggxtest::run_user_samples(sampler, program, c.params, test_range);
        SamplePlanes runtime = ggxtest::enqueue_samples(sampler, sampler.queue(), c.params, test_range);
        CHECK(same_bits(mine, runtime));
    }
    // Control: the comparison tells neighbouring samples apart.
    ggxcl::SampleParams p{ggxcl::Method::caps, 0.3f, 0.3f, ggxcl::view_from_angles(45, 0)};
    ggxcl::SampleRange shifted = test_range;
    shifted.first += 1;
    cl::Program program = ggxcl::build_user_program(sampler.context(), sampler.device(),
                                                    ggxtest::user_samples_source(true));
    CHECK_FALSE(same_bits(ggxtest::run_user_samples(sampler, program, p, shifted),
                          ggxtest::enqueue_samples(sampler, sampler.queue(), p, test_range)));
}

TEST_CASE("prepending the embedded headers gives the bits of including them")
{
    auto& sampler = ggxtest::sampler();
    ggxcl::SampleParams p{ggxcl::Method::bounded, 0.3f, 0.1f, ggxcl::view_from_angles(40, 75)};
    cl::Program prepended(sampler.context(),
                          ggxcl::kernel_source("ggx_samplers.h") + ggxtest::user_samples_source(false));
    const std::string options =
        ggxcl::device_options(sampler.device()) + ggxcl::precision_options(sampler.device(), p.precision);
    prepended.build({sampler.device()}, options.c_str());
    SamplePlanes mine = ggxtest::run_user_samples(sampler, prepended, p, test_range);
    CHECK(same_bits(mine, ggxtest::enqueue_samples(sampler, sampler.queue(), p, test_range)));
}

TEST_CASE("headers written by write_device_headers serve as GGXCL_DEVICE_INCLUDE_DIR")
{
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("ggxcl-user-kernels-" + std::to_string(::getpid()));
    ggxcl::write_device_headers(dir.string());
    ::setenv("GGXCL_DEVICE_INCLUDE_DIR", dir.c_str(), 1);
    CHECK(ggxcl::device_include_dir() == dir.string());
    CHECK(ggxcl::device_include_option() == "-I" + dir.string());
    auto& sampler = ggxtest::sampler();
    ggxcl::SampleParams p{ggxcl::Method::heitz, 0.5f, 0.5f, ggxcl::view_from_angles(80, 0)};
    cl::Program program =
        ggxcl::build_user_program(sampler.context(), sampler.device(), ggxtest::user_samples_source(true));
    CHECK(same_bits(ggxtest::run_user_samples(sampler, program, p, test_range),
                    ggxtest::enqueue_samples(sampler, sampler.queue(), p, test_range)));

    ::setenv("GGXCL_DEVICE_INCLUDE_DIR", (dir / "missing").c_str(), 1);
    CHECK_THROWS_WITH_AS(ggxcl::device_include_dir(), doctest::Contains("GGXCL_DEVICE_INCLUDE_DIR"),
                         ggxcl::InvalidArgument);
    ::unsetenv("GGXCL_DEVICE_INCLUDE_DIR");
    fs::remove_all(dir);
}

TEST_CASE("without GGXCL_DEVICE_INCLUDE_DIR the include directory holds the library's headers")
{
    ::unsetenv("GGXCL_DEVICE_INCLUDE_DIR");
    const std::filesystem::path dir = ggxcl::device_include_dir();
    for (const char* header : {"ggx_samplers.h", "ggx_math.h", "ggx_philox.h", "ggx_world.h"}) {
        CAPTURE(header);
        std::ifstream in(dir / header, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        CHECK(text.str() == ggxcl::kernel_source(header));  // the library's own text, not a stale copy
    }
}

TEST_CASE("each device header compiles alone, and all of them together")
{
    auto& sampler = ggxtest::sampler();
    const std::string probe = "\n__kernel void probe(__global float* x) { x[0] = 1.0f; }\n";
    const std::string options = "-DGGX_METHOD=3 -DGGX_BINS_Z=4 -DGGX_BINS_PHI=8";
    std::string all;
    for (const std::string& file : ggxcl::kernel_files()) {
        if (!ggxtest::ends_with(file, ".h") || ggxtest::is_shader_only_header(file))
            continue;  // GLSL and HLSL alone
        INFO(file);
        const std::string include = "#include \"" + file + "\"\n";
        // ggx_bulk_params.h and ggx_bulk_sample.h are the bulk kernels' headers: they need the method id; ggx_histogram_bin.h
        // the histogram's bin counts.
        CHECK_NOTHROW(ggxcl::build_user_program(sampler.context(), sampler.device(), include + probe, options));
        all += include;
    }
    CHECK_NOTHROW(ggxcl::build_user_program(sampler.context(), sampler.device(), all + probe, options));
}

TEST_CASE("a failed user build throws BuildError with the options and the log")
{
    auto& sampler = ggxtest::sampler();
    const std::string bad = "#include \"ggx_samplers.h\"\n"
                            "__kernel void k(__global float* x) { x[0] = ggx_nonexistent(1.0f); }\n";
    try {
        ggxcl::build_user_program(sampler.context(), sampler.device(), bad, "-DUSER_FLAG=1");
        FAIL("the build should fail");
    } catch (const ggxcl::BuildError& e) {
        const std::string what = e.what();
        CHECK(what.find("CL_BUILD_PROGRAM_FAILURE") != std::string::npos);
        CHECK(what.find("-DUSER_FLAG=1") != std::string::npos);
        CHECK(what.find(ggxcl::device_include_option()) != std::string::npos);
        CHECK(e.log().find("ggx_nonexistent") != std::string::npos);
    }
}

TEST_CASE("every name the device headers define starts with ggx_ or GGX_")
{
    for (const std::string& file : ggxcl::kernel_files()) {
        if (file.size() < 2 || file.substr(file.size() - 2) != ".h")
            continue;  // the programs (.cl, .comp, .hlsl) are built alone, never included
        INFO(file);
        std::string offenders;
        for (const std::string& name : ggxtest::unprefixed_names(ggxcl::kernel_source(file)))
            offenders += name + " ";
        CHECK_MESSAGE(offenders.empty(), "unprefixed: " << offenders);
    }
}

TEST_CASE("the name check sees the headers' real names")
{
    const std::vector<std::string> names = ggxtest::defined_names(ggxcl::kernel_source("ggx_world.h"));
    auto has = [&](const char* name) { return std::find(names.begin(), names.end(), name) != names.end(); };
    for (const char* expected : {"GGX_INLINE", "GGX_METHOD_LIST", "GGX_METHOD_CAPS", "GGX_PHILOX_M", "ggx_vec3", "ggx_sample",
                                 "ggx_basis", "ggx_uniforms", "ggx_sample_caps", "ggx_pdf_method", "ggx_G2",
                                 "ggx_sample_world"})
        CHECK_MESSAGE(has(expected), expected);
    CHECK(names.size() > 80);
}

TEST_CASE("negative control: the name check reports every kind of unprefixed name")
{
    const std::string synthetic = R"CL(
// a comment naming not_a_name(
#define PI 3.14159f
#define SQUARE(x) ((x) * (x))
#define GGX_FINE 1
typedef struct { float x, y; } vec2;
struct ray { float t; };
enum mode { MODE_A, ggx_mode_b = 2 };
__constant float table[2] = {1.0f, 2.0f};
float scale = 2.0f, offset;
inline float dot3(float a, float b) { float local = a * b; return local; }
GGX_INLINE float ggx_fine(float v) { return v; }
__kernel void entry(__global float* out) { out[0] = dot3(1.0f, 2.0f); }
)CL";
    const std::vector<std::string> expected{"PI",   "SQUARE", "vec2",   "ray",  "mode", "MODE_A",
                                            "table", "scale", "offset", "dot3", "entry"};
    CHECK(ggxtest::unprefixed_names(synthetic) == expected);
}

TEST_CASE("one range split over two samplers on two contexts gives the one-sampler bits")
{
    // A pipeline's multi-device split: each device (here the same device in
    // two contexts) has its own Sampler, queue and buffers and enqueues a
    // range of sample indices; sample k depends on (seed, k) alone.
    const cl::Device device = ggxtest::sampler().device();
    ggxcl::SampleParams p{ggxcl::Method::caps, 0.15f, 0.6f, ggxcl::view_from_angles(72, 10)};
    const ggxcl::SampleRange whole{77, 5000, 40001};
    const std::uint64_t split = 15013;
    const ggxcl::SampleRange parts[2] = {{77, 5000, split}, {77, 5000 + split, whole.count - split}};

    std::vector<std::unique_ptr<ggxcl::Sampler>> samplers;
    std::vector<ggxtest::PendingSamples> pending;
    for (const ggxcl::SampleRange& part : parts) {  // both enqueued before either is read: they run side by side
        cl::Context context(device);
        samplers.push_back(std::make_unique<ggxcl::Sampler>(context, device));
        pending.push_back(ggxtest::start_samples(*samplers.back(), cl::CommandQueue(context, device), p, part));
    }
    SamplePlanes joined = ggxtest::join_planes(ggxtest::finish_samples(pending[0]),
                                               ggxtest::finish_samples(pending[1]));
    auto& one = ggxtest::sampler();
    CHECK(same_bits(joined, ggxtest::enqueue_samples(one, one.queue(), p, whole)));
}
