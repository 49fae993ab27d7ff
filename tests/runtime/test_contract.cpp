// test_contract.cpp - the kernels keep the contract of kernels/ggx_contract.h:
// every bulk kernel, built with -cl-kernel-arg-info, names at each argument
// position of the contract the argument the runtime sets there (negative
// control: a kernel with two arguments swapped is caught); an unknown method
// id or write mask does not build; and the device dispatchers give the
// fallback sample ("no sample") for an id that is no method, not some
// method's sample.  (The host's enums are checked against the contract at
// compile time, lib/src/core/device_contract.hpp.)
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "device_fixture.hpp"
#include "ggx_quadrature.hpp"
#include "ggx_contract.h"

namespace {

using Expected = std::vector<std::pair<int, std::string>>;  // position, argument name

// The argument names of kernel `name` built from `source`.
std::vector<std::string> argument_names(const std::string& source, const std::string& options,
                                        const std::string& name)
{
    auto& s = ggxtest::sampler();
    cl::Program program = ggxcl::build_user_program(s.context(), s.device(), source, options + " -cl-kernel-arg-info");
    cl::Kernel kernel(program, name.c_str());
    std::vector<std::string> names;
    for (cl_uint k = 0; k < kernel.getInfo<CL_KERNEL_NUM_ARGS>(); ++k) {
        std::string arg = kernel.getArgInfo<CL_KERNEL_ARG_NAME>(k);
        names.push_back(arg.c_str());  // without a trailing NUL
    }
    return names;
}

// The positions of the contract where `names` differ from `expected`, as text; empty when none.
std::string mismatches(const std::vector<std::string>& names, const Expected& expected, std::size_t total)
{
    std::string found;
    if (names.size() != total)
        found += "count " + std::to_string(names.size()) + " (expected " + std::to_string(total) + "); ";
    for (const auto& [position, name] : expected)
        if (position >= int(names.size()) || names[position] != name)
            found += std::to_string(position) + ": " + (position < int(names.size()) ? names[position] : "-") +
                     " (expected " + name + "); ";
    return found;
}

// The parameter arguments of GGX_PARAM_KERNEL_ARGS from `first`: the values, the buffers, their offsets.
Expected param_arguments(int first)
{
    const char* names[GGX_PARAM_ARG_COUNT] = {"view_x",   "view_y",   "view_z",    "alpha_x",     "alpha_y",
                                              "normal_x", "normal_y", "normal_z",  "eta",         "view_in",
                                              "alpha_in", "normal_in", "uniforms_in", "view_at",  "alpha_at",
                                              "normal_at", "uniforms_at"};
    Expected e;
    for (int k = 0; k < GGX_PARAM_ARG_COUNT; ++k)
        e.push_back({first + k, names[k]});
    return e;
}

Expected sampling_head()
{
    Expected e = {{GGX_ARG_SEED, "seed"}, {GGX_ARG_FIRST, "first"}, {GGX_ARG_COUNT, "count"}};
    for (auto& p : param_arguments(GGX_ARG_PARAMS))
        e.push_back(p);
    return e;
}

Expected with(Expected e, const Expected& more)
{
    e.insert(e.end(), more.begin(), more.end());
    return e;
}

const char* const method_options = "-DGGX_METHOD=3";
const char* const histogram_options = "-DGGX_METHOD=3 -DGGX_BINS_Z=4 -DGGX_BINS_PHI=8";

} // namespace

TEST_CASE("every bulk kernel has the contract's argument at each of its positions")
{
    const std::string bulk = ggxcl::kernel_source("ggx_bulk.cl");
    const Expected sample_outputs = {{GGX_ARG_STRIDE, "stride"},
                                     {GGX_ARG_OUTPUTS + GGX_FIELD_M, "m_out"},
                                     {GGX_ARG_OUTPUTS + GGX_FIELD_O, "o_out"},
                                     {GGX_ARG_OUTPUTS + GGX_FIELD_PDF_M, "pdf_m_out"},
                                     {GGX_ARG_OUTPUTS + GGX_FIELD_PDF_O, "pdf_o_out"},
                                     {GGX_ARG_OUTPUTS + GGX_FIELD_WEIGHT, "weight_out"},
                                     {GGX_ARG_OUTPUTS + GGX_FIELD_U, "u_out"},
                                     {GGX_ARG_OUTPUT_OFFSETS + GGX_FIELD_M, "m_at"},
                                     {GGX_ARG_OUTPUT_OFFSETS + GGX_FIELD_O, "o_at"},
                                     {GGX_ARG_OUTPUT_OFFSETS + GGX_FIELD_PDF_M, "pdf_m_at"},
                                     {GGX_ARG_OUTPUT_OFFSETS + GGX_FIELD_PDF_O, "pdf_o_at"},
                                     {GGX_ARG_OUTPUT_OFFSETS + GGX_FIELD_WEIGHT, "weight_at"},
                                     {GGX_ARG_OUTPUT_OFFSETS + GGX_FIELD_U, "u_at"}};
    for (const char* name : {"ggx_sample_bulk", "ggx_sample_bulk_tail"}) {
        CAPTURE(name);
        CHECK(mismatches(argument_names(bulk, method_options, name), with(sampling_head(), sample_outputs),
                         GGX_ARG_OUTPUT_OFFSETS + GGX_FIELD_COUNT) == "");
    }
    Expected pdf = {{GGX_PDF_ARG_COUNT, "count"},
                    {GGX_PDF_ARG_STRIDE, "stride"},
                    {GGX_PDF_ARG_DIRECTIONS, "o_in"},
                    {GGX_PDF_ARG_PDFS, "pdf_out"},
                    {GGX_PDF_ARG_DIRECTIONS_OFFSET, "o_at"},
                    {GGX_PDF_ARG_PDFS_OFFSET, "pdf_at"}};
    for (const char* name : {"ggx_pdf_bulk", "ggx_pdf_bulk_tail"}) {
        CAPTURE(name);
        CHECK(mismatches(argument_names(bulk, method_options, name), with(pdf, param_arguments(GGX_PDF_ARG_PARAMS)),
                         GGX_PDF_ARG_PDFS_OFFSET + 1) == "");
    }
    CHECK(mismatches(argument_names(ggxcl::kernel_source("ggx_furnace.cl"), method_options, "ggx_furnace_bulk"),
                     with(sampling_head(),
                          {{GGX_ARG_STRIDE, "stride"}, {GGX_ARG_OUTPUTS, "sums_out"}, {GGX_ARG_SUMS_OFFSET, "sums_at"}}),
                     GGX_ARG_SUMS_OFFSET + 1) == "");
    const std::string histogram = ggxcl::kernel_source("ggx_histogram.cl");
    for (auto [name, output] : {std::pair<const char*, const char*>{"ggx_histogram", "counts"},
                                {"ggx_histogram_bins", "bins"},
                                {"ggx_histogram_bins_tail", "bins"}}) {
        CAPTURE(name);
        CHECK(mismatches(argument_names(histogram, histogram_options, name),
                         with(sampling_head(), {{GGX_ARG_STRIDE, "per_item"}, {GGX_ARG_OUTPUTS, output}}),
                         GGX_ARG_OUTPUTS + 1) == "");
    }
    CHECK(mismatches(argument_names(histogram, histogram_options, "ggx_histogram_count"),
                     {{GGX_COUNT_ARG_BINS, "bins"},
                      {GGX_COUNT_ARG_COUNT, "count"},
                      {GGX_COUNT_ARG_PER_ITEM, "per_item"},
                      {GGX_COUNT_ARG_COUNTS, "counts"}},
                     GGX_COUNT_ARG_COUNTS + 1) == "");
}

TEST_CASE("control: a kernel with two arguments swapped breaks the contract, and the check says where")
{
    const std::string swapped = "#include \"ggx_bulk_params.h\"\n"
                                "__kernel void swapped(ulong seed, ulong first, uint stride, uint count, "
                                "GGX_PARAM_KERNEL_ARGS, __global float* sums) { sums[0] = (float)(count + stride); }\n";
    std::string found = mismatches(argument_names(swapped, method_options, "swapped"),
                                   with(sampling_head(), {{GGX_ARG_STRIDE, "stride"}, {GGX_ARG_OUTPUTS, "sums"}}),
                                   GGX_ARG_OUTPUTS + 1);
    CHECK(found.find("2: stride (expected count)") != std::string::npos);
    CHECK(found.find("3: count (expected stride)") != std::string::npos);
}

TEST_CASE("an unknown method id or write mask does not build")
{
    auto& s = ggxtest::sampler();
    const std::string bulk = ggxcl::kernel_source("ggx_bulk.cl");
    for (const std::string& options :
         {"-DGGX_METHOD=" + std::to_string(GGX_METHOD_COUNT), std::string("-DGGX_METHOD=-1"),
          "-DGGX_METHOD=3 -DGGX_WRITE_MASK=" + std::to_string(1 << GGX_FIELD_COUNT)}) {
        CAPTURE(options);
        try {
            ggxcl::build_user_program(s.context(), s.device(), bulk, options);
            FAIL("built");
        } catch (const ggxcl::BuildError& e) {
            const std::string what = e.what();
            CHECK((what.find("not a method id") != std::string::npos ||
                   what.find("GGX_WRITE_MASK") != std::string::npos));
        }
    }
    CHECK_NOTHROW(ggxcl::build_user_program(s.context(), s.device(), bulk,
                                            "-DGGX_METHOD=3 -DGGX_WRITE_MASK=" +
                                                std::to_string((1 << GGX_FIELD_COUNT) - 1)));
}

TEST_CASE("the device dispatchers give the fallback sample for an id that is no method")
{
    auto& s = ggxtest::sampler();
    const std::string source = "#include \"ggx_samplers.h\"\n"
                               "__kernel void dispatch(int method, __global float* out) {\n"
                               "  ggx_vec3 n = ggx_vec3_make(0.0f, 0.0f, 1.0f), i = ggx_vec3_make(0.6f, 0.0f, 0.8f);\n"
                               "  ggx_sample r = ggx_sample_method(method, n, i, 0.3f, 0.3f, 0.3f, 0.7f);\n"
                               "  out[0] = r.m.x; out[1] = r.m.y; out[2] = r.m.z; out[3] = r.o.x; out[4] = r.o.y;\n"
                               "  out[5] = r.o.z; out[6] = r.pdf_m; out[7] = r.pdf_o; out[8] = r.weight;\n"
                               "  out[9] = ggx_pdf_method(method, n, i, ggx_vec3_make(-0.6f, 0.0f, 0.8f), 0.3f, 0.3f);\n"
                               "}\n";
    cl::Program program = ggxcl::build_user_program(s.context(), s.device(), source, "");
    cl::Kernel kernel(program, "dispatch");
    cl::Buffer out(s.context(), CL_MEM_READ_WRITE, 10 * sizeof(float));
    auto run = [&](int method) {
        kernel.setArg(0, cl_int(method));
        kernel.setArg(1, out);
        s.queue().enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(1));
        std::vector<float> r(10);
        s.queue().enqueueReadBuffer(out, CL_TRUE, 0, r.size() * sizeof(float), r.data());
        return r;
    };
    for (int id : {GGX_METHOD_COUNT, -1, 99}) {
        CAPTURE(id);
        CHECK(run(id) == std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 0, 0});
    }
    std::vector<float> caps = run(GGX_METHOD_CAPS);  // control: a method id gives its sample
    CHECK(caps[8] > 0.0f);
    CHECK(caps[9] > 0.0f);
}

TEST_CASE("the reference bridge maps every method both ways, by name")
{
    for (ggxcl::Method m : ggxcl::all_methods) {
        CAPTURE(ggxcl::method_name(m));
        const ggxref::Method r = ggxbridge::reference_method(m);
        CHECK(std::string(ggxref::method_name(r)) == std::string(ggxcl::method_name(m)));
        CHECK(ggxbridge::library_method(r) == m);
    }
    CHECK_THROWS_AS(ggxbridge::reference_method(ggxcl::Method(GGX_METHOD_COUNT)), std::logic_error);
}

TEST_CASE("the reference bridge gives the reference unit vectors: its bins near -n sum to 1")
{
    // A unit float view at 179.9 degrees is off unit by ~5e-8, a large part of 1 - iz^2 ~ 3e-6.
    const ggxcl::SampleParams p = ggxcl::normalized(ggxtest::to_library(
        ggxref::Method::heitz, ggxref::Params{0.3, 0.3, ggxref::Vec3{std::sin(179.9 * M_PI / 180.0), 0.0,
                                                                    std::cos(179.9 * M_PI / 180.0)}}));
    const ggxref::Params ref = ggxbridge::reference_params(p);
    CHECK(std::fabs(ggxref::dot(ref.i, ref.i) - 1.0) <= 1e-15);
    CHECK(std::fabs(ggxref::dot(ref.n, ref.n) - 1.0) <= 1e-15);
    auto sum_of = [](const ggxref::Params& params) {
        double sum = 0.0;
        for (double b : ggxref::bin_probabilities(ggxref::Method::heitz, params, 16, 32))
            sum += b;
        return sum;
    };
    CHECK(std::fabs(sum_of(ref) - 1.0) <= 1e-8);
    // Control: the float view taken as it is gives bins that do not sum to 1.
    ggxref::Params raw = ref;
    raw.i = {p.view.x, p.view.y, p.view.z};
    CHECK(std::fabs(sum_of(raw) - 1.0) > 1e-3);
}
