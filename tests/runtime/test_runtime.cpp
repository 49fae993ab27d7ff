// test_runtime.cpp - the C++ runtime: results independent of chunking and
// range splits, caller buffers on the caller's queue, per-sample
// parameters, field selection, program caching, device selection, the
// errors for bad arguments and failed builds, one validation per call, and
// the build options of the precision modes.
#include <doctest/doctest.h>

#include <cstdlib>
#include <cstring>
#include <iterator>

#include "bit_compare.hpp"
#include "device_fixture.hpp"
#include "device_quirks.hpp"
#include "kernel_launch.hpp"
#include "program_cache.hpp"

namespace {

using ggxcl::Field;
using ggxtest::message_of;
using ggxtest::same_bits;

ggxcl::SampleParams test_params(ggxcl::Method method = ggxcl::Method::heitz)
{
    ggxcl::SampleParams p;
    p.method = method;
    p.alpha_x = 0.25f;
    p.alpha_y = method == ggxcl::Method::caps_iso ? 0.25f : 0.6f;
    p.view = ggxcl::view_from_angles(50, 20);
    return p;
}

} // namespace

TEST_CASE("results are bit-identical whatever the chunk size")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    const std::uint64_t saved = s.chunk_size();
    for (ggxcl::Method method : ggxcl::all_methods) {
        ggxcl::SampleParams p = test_params(method);
        s.set_chunk_size(1 << 20);
        ggxcl::SampleSet whole = s.generate(p, {5, 123, 10007}, ggxcl::FieldSet::all());
        for (std::uint64_t chunk : {1000ull, 4099ull, 256ull}) {
            s.set_chunk_size(chunk);
            CAPTURE(chunk);
            CHECK(same_bits(whole, s.generate(p, {5, 123, 10007}, ggxcl::FieldSet::all())));
        }
    }
    s.set_chunk_size(saved);
}

TEST_CASE("chunk views (mapped on CPU devices) give generate's samples, chunk by chunk in order")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    const std::uint64_t saved = s.chunk_size(), count = 10007;
    ggxcl::SampleParams p = test_params(ggxcl::Method::bounded);
    ggxcl::SampleSet whole = s.generate(p, {5, 123, count}, ggxcl::FieldSet::all());
    s.set_chunk_size(4099);
    ggxcl::SampleSet gathered;
    gathered.count = count;
    std::vector<float>* parts[] = {&gathered.m,     &gathered.o,      &gathered.pdf_m,
                                   &gathered.pdf_o, &gathered.weight, &gathered.u};
    static_assert(std::size(parts) == ggxcl::all_fields.size());
    std::uint64_t expected_offset = 0;
    int chunks = 0;
    s.generate_chunk_views(p, {5, 123, count}, ggxcl::FieldSet::all(), [&](const ggxcl::SampleView& v, std::uint64_t offset) {
        CHECK(offset == expected_offset);
        CHECK(v.stride >= v.count);
        for (ggxcl::Field f : ggxcl::all_fields) {
            parts[int(f)]->resize(ggxcl::field_columns(f) * count);
            for (int c = 0; c < ggxcl::field_columns(f); ++c)
                std::copy_n(v.column_source(f) + c * v.stride, v.count, parts[int(f)]->data() + c * count + offset);
        }
        expected_offset += v.count;
        ++chunks;
    });
    s.set_chunk_size(saved);
    CHECK(chunks == 3);
    CHECK(expected_offset == count);
    CHECK(same_bits(whole, gathered));
}

// A sink that throws leaves the next chunk's copy in flight; the call must
// wait for it before freeing its host memory.  On Mesa rusticl 22.3 (whose
// clFinish returns at once after a clFlush) 40 rounds of this corrupted the
// heap in 3 of 3 runs before the runtime waited on a marker instead.
TEST_CASE("a sink that throws stops the call after whole chunks, with no copy left in flight")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    const std::uint64_t saved = s.chunk_size(), chunk = 1 << 16;
    s.set_chunk_size(chunk);
    ggxcl::SampleParams p = test_params(ggxcl::Method::caps);
    struct Stop {};
    for (int round = 0; round < 40; ++round) {
        const int stop_at = 2 + round % 4;
        int delivered = 0;
        std::uint64_t expected_offset = 0;
        CHECK_THROWS_AS(s.generate_chunks(p, {1, 0, 64 * chunk}, {Field::weight},
                                          [&](const ggxcl::SampleSet& c, std::uint64_t offset) {
                                              CHECK(offset == expected_offset);
                                              expected_offset += c.count;
                                              if (++delivered == stop_at)
                                                  throw Stop{};
                                          }),
                        Stop);
        CHECK(delivered == stop_at);
        // Fresh allocations of the size of the abandoned copy: a late write into freed memory corrupts them.
        ggxcl::SampleSet after = s.generate(p, {2, 0, 3 * chunk}, {Field::m, Field::weight});
        CHECK(after.weight.size() == 3 * chunk);
    }
    s.set_chunk_size(saved);
}

TEST_CASE("consecutive ranges concatenate to the whole range")
{
    ggxcl::SampleParams p = test_params();
    ggxcl::SampleSet whole = ggxtest::sampler().generate(p, {9, 0, 5000}, {Field::m});
    ggxcl::SampleSet head = ggxtest::sampler().generate(p, {9, 0, 1234}, {Field::m});
    ggxcl::SampleSet tail = ggxtest::sampler().generate(p, {9, 1234, 5000 - 1234}, {Field::m});
    for (int c = 0; c < 3; ++c) {
        CHECK(std::memcmp(whole.m.data() + c * 5000, head.m.data() + c * 1234, 1234 * 4) == 0);
        CHECK(std::memcmp(whole.m.data() + c * 5000 + 1234, tail.m.data() + c * 3766, 3766 * 4) == 0);
    }
}

TEST_CASE("only the requested fields are returned, with the same values")
{
    ggxcl::SampleParams p = test_params(ggxcl::Method::caps);
    ggxcl::SampleSet all = ggxtest::sampler().generate(p, {3, 0, 3000}, ggxcl::FieldSet::all());
    ggxcl::SampleSet some = ggxtest::sampler().generate(p, {3, 0, 3000}, {Field::pdf_o, Field::m});
    CHECK(same_bits(all.m, some.m));
    CHECK(same_bits(all.pdf_o, some.pdf_o));
    CHECK(some.o.empty());
    CHECK(some.pdf_m.empty());
    CHECK(some.weight.empty());
}

TEST_CASE("program variants are built once per request shape and cached")
{
    ggxcl::Sampler local;
    ggxcl::SampleParams p = test_params(ggxcl::Method::bounded);
    local.generate(p, {1, 0, 100}, {Field::m});
    local.generate(p, {2, 50, 300}, {Field::m});
    CHECK(local.programs_built() == 1);
    local.generate(p, {1, 0, 100}, {Field::m, Field::pdf_o});
    CHECK(local.programs_built() == 2);
}

TEST_CASE("enqueue writes into the caller's buffers on the caller's queue")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    ggxcl::SampleParams p = test_params(ggxcl::Method::caps);
    const std::uint32_t count = 3000, stride = 3100;
    cl::CommandQueue my_queue(s.context(), s.device());
    ggxcl::DeviceOutputs out;
    out.m = cl::Buffer(s.context(), CL_MEM_READ_WRITE, 3 * stride * sizeof(float));
    out.weight = cl::Buffer(s.context(), CL_MEM_READ_WRITE, stride * sizeof(float));
    cl::Event done = s.enqueue(my_queue, p, {4, 77, count}, out, stride);
    done.wait();
    CHECK(done.getInfo<CL_EVENT_COMMAND_EXECUTION_STATUS>() == CL_COMPLETE);
    std::vector<float> m(3 * stride), w(stride);
    my_queue.enqueueReadBuffer(out.m, CL_TRUE, 0, m.size() * 4, m.data());
    my_queue.enqueueReadBuffer(out.weight, CL_TRUE, 0, w.size() * 4, w.data());
    ggxcl::SampleSet host = s.generate(p, {4, 77, count}, {Field::m, Field::weight});
    for (int c = 0; c < 3; ++c)
        CHECK(std::memcmp(m.data() + c * stride, host.m.data() + c * count, count * 4) == 0);
    CHECK(std::memcmp(w.data(), host.weight.data(), count * 4) == 0);
}

TEST_CASE("per-sample parameters give what uniform batches give")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    ggxcl::SampleParams a = test_params(ggxcl::Method::caps_iso), b = a;
    b.alpha_x = b.alpha_y = 0.9f;
    b.view = ggxcl::view_from_angles(10, 200);
    b.normal = {0.3f, -0.2f, 0.9f};
    const std::uint64_t count = 2000;
    ggxcl::PerSampleInputs per;
    for (std::uint64_t j = 0; j < count; ++j) {
        const ggxcl::SampleParams& q = (j % 3 == 0) ? b : a;
        per.views.push_back(q.view);
        per.alphas.push_back({q.alpha_x, q.alpha_y});
        per.normals.push_back(q.normal);
    }
    ggxcl::SampleSet mixed = s.generate(a, {8, 0, count}, {Field::m, Field::pdf_o}, per);
    ggxcl::SampleSet only_a = s.generate(a, {8, 0, count}, {Field::m, Field::pdf_o});
    ggxcl::SampleSet only_b = s.generate(b, {8, 0, count}, {Field::m, Field::pdf_o});
    std::size_t mismatches = 0;
    for (std::uint64_t j = 0; j < count; ++j) {
        const ggxcl::SampleSet& expected = (j % 3 == 0) ? only_b : only_a;
        mismatches += mixed.pdf_o[j] != expected.pdf_o[j];
        for (int c = 0; c < 3; ++c)
            mismatches += mixed.m[c * count + j] != expected.m[c * count + j];
    }
    CHECK(mismatches == 0);
}

TEST_CASE("bad arguments throw InvalidArgument naming the parameter, value and range")
{
    ggxcl::Sampler& s = ggxtest::sampler();
    ggxcl::SampleParams p = test_params();
    auto generate = [&](ggxcl::SampleParams q, std::uint64_t count = 10, ggxcl::FieldSet f = {Field::m}) {
        s.generate(q, {0, 0, count}, f);
    };
    ggxcl::SampleParams bad = p;
    bad.alpha_x = 0.0f;
    CHECK(message_of<ggxcl::InvalidArgument>([&] { generate(bad); }) ==
          "invalid alpha_x '0': allowed is a number from 1e-30 to 1e30");
    bad.alpha_x = 2e30f;
    CHECK(message_of<ggxcl::InvalidArgument>([&] { generate(bad); }) ==
          "invalid alpha_x '2e+30': allowed is a number from 1e-30 to 1e30");
    CHECK(message_of<ggxcl::InvalidArgument>([] { ggxcl::view_from_angles(200.0, 0.0); }) ==
          "invalid theta '200': allowed is degrees from 0 to 180");
    CHECK(message_of<ggxcl::InvalidArgument>([] { ggxcl::view_from_angles(0.0, -400.0); }) ==
          "invalid phi '-400': allowed is degrees from -360 to 360");
    bad = p;
    bad.alpha_y = std::nanf("");
    CHECK(message_of<ggxcl::InvalidArgument>([&] { generate(bad); }).find("alpha_y 'nan'") != std::string::npos);
    bad = p;
    bad.view = {0, 0, 0};
    CHECK(message_of<ggxcl::InvalidArgument>([&] { generate(bad); }).find("view '0,0,0'") != std::string::npos);
    bad = p;
    bad.method = ggxcl::Method::caps_iso;
    CHECK(message_of<ggxcl::InvalidArgument>([&] { generate(bad); }).find("caps-iso") != std::string::npos);
    CHECK(message_of<ggxcl::InvalidArgument>([&] { generate(p, 0); }) ==
          "invalid count '0': allowed is at least 1 sample");
    CHECK(message_of<ggxcl::InvalidArgument>([&] { generate(p, 10, {}); }).find("fields") != std::string::npos);
    CHECK(message_of<ggxcl::InvalidArgument>([] { ggxcl::parse_method("walter"); }) ==
          "invalid method 'walter': allowed is one of ndf, heitz, heitz2017, caps, caps-iso, bounded");
    CHECK(message_of<ggxcl::InvalidArgument>([&] { s.set_chunk_size(0); }).find("chunk size '0'") != std::string::npos);
    CHECK(message_of<ggxcl::InvalidArgument>([&] { s.generate(p, {ggxcl::max_seed + 1, 0, 10}, {Field::m}); }) ==
          "invalid seed '4294967296': allowed is 0 .. 2^32 - 1 = 4294967295 (the generators' 32-bit key)");
    CHECK_NOTHROW(s.generate(p, {ggxcl::max_seed, 0, 10}, {Field::m}));
}

TEST_CASE("devices are selected by index, by name part, or by GGXCL_DEVICE")
{
    std::vector<ggxcl::DeviceInfo> devices = ggxcl::list_devices();
    REQUIRE(!devices.empty());
    CHECK(ggxcl::select_device("0").label() == devices[0].label());
    std::string part = devices.back().name.substr(0, 6);
    CHECK(ggxcl::select_device(part).label().find(part) != std::string::npos);
    std::string error = message_of<ggxcl::DeviceError>([] { ggxcl::select_device("no-such-device-xyz"); });
    CHECK(error.find("no-such-device-xyz") != std::string::npos);
    CHECK(error.find(devices[0].label()) != std::string::npos);  // lists what exists
    CHECK(message_of<ggxcl::DeviceError>([&] { ggxcl::select_device(std::to_string(devices.size())); })
              .find("no OpenCL device matches") != std::string::npos);
    // GGXCL_DEVICE is changed here and restored after, so the test cases
    // that follow run on the device the suite was started on.
    const char* selected = std::getenv("GGXCL_DEVICE");
    const std::string saved = selected ? selected : "";
    ::setenv("GGXCL_DEVICE", "no-such-device-xyz", 1);
    CHECK(message_of<ggxcl::DeviceError>([] { ggxcl::select_device(); }).find("GGXCL_DEVICE") != std::string::npos);
    ::setenv("GGXCL_DEVICE", std::to_string(devices.size() - 1).c_str(), 1);
    CHECK(ggxcl::select_device().label() == devices.back().label());
    if (selected)
        ::setenv("GGXCL_DEVICE", saved.c_str(), 1);
    else
        ::unsetenv("GGXCL_DEVICE");
    CHECK(ggxcl::select_device().device() == ggxtest::sampler().device()());  // restored
}

TEST_CASE("every device tells its OpenCL version and limits, and is selected by its vendor too")
{
    for (const ggxcl::DeviceInfo& d : ggxcl::list_devices()) {
        CAPTURE(d.label());
        CHECK(d.opencl_version.rfind("OpenCL ", 0) == 0);
        CHECK(d.opencl_c_version.rfind("OpenCL C ", 0) == 0);
        CHECK(d.max_work_group_size >= 1);
        CHECK(d.max_alloc_bytes > 0);
        CHECK(d.max_alloc_bytes <= d.global_mem_bytes);
        CHECK(d.local_mem_bytes >= 16 * 1024);  // the minimum OpenCL 1.2 promises
        CHECK(!d.vendor.empty());
        CHECK(ggxcl::select_device(d.vendor).vendor == d.vendor);
    }
}

TEST_CASE("a failed build throws BuildError with the CL error name, options and build log")
{
    ggxcl::ProgramCache cache(ggxtest::sampler().context());
    std::string message = message_of<ggxcl::BuildError>(
        [&] { cache.get(ggxtest::sampler().device(), "ggx_bulk.cl", "-DGGX_WRITE_M=1"); });
    CHECK(message.find("CL_BUILD_PROGRAM_FAILURE") != std::string::npos);
    CHECK(message.find("-DGGX_WRITE_M=1") != std::string::npos);
    CHECK(message.find("ggx_bulk.cl") != std::string::npos);  // #line markers name the file
    CHECK(message.find("GGX_METHOD") != std::string::npos);   // the #error text of the log
}

TEST_CASE("embedded kernel sources are self-contained with #line markers")
{
    const std::string& source = ggxcl::kernel_source("ggx_samplers.h");
    CHECK(source.find("#include \"") == std::string::npos);
    CHECK(source.find("#line 1 \"ggx_sample_caps.h\"") != std::string::npos);
    CHECK(message_of<ggxcl::InvalidArgument>([] { ggxcl::kernel_source("nope.cl"); }).find("ggx_bulk.cl") !=
          std::string::npos);
}

TEST_CASE("device histogram counts what the host counts from the same samples")
{
    for (ggxcl::Field direction : {Field::o, Field::m}) {
        ggxcl::SampleParams p = test_params(ggxcl::Method::ndf);
        const std::uint64_t count = 200000;
        const int nz = 16, nphi = 32;
        ggxcl::Histogram device = ggxtest::sampler().histogram(p, {21, 40, count}, nz, nphi, direction);
        ggxcl::SampleSet s = ggxtest::sampler().generate(p, {21, 40, count}, {direction});
        const std::vector<float>& d = s.column_source(direction);
        std::vector<std::uint64_t> host = ggxtest::histogram_of(d, count, nz, nphi);
        CHECK(device.total() == count);
        CHECK(device.non_finite == 0);
        std::uint64_t moved = 0;  // samples on a bin edge may round to the neighbour in float
        for (std::size_t b = 0; b < host.size(); ++b)
            moved += device.counts[b] > host[b] ? device.counts[b] - host[b] : host[b] - device.counts[b];
        CHECK(moved <= count / 10000);
    }
    CHECK_THROWS_AS(ggxtest::sampler().histogram(test_params(), {0, 0, 10}, 0, 4), ggxcl::InvalidArgument);
    try {
        ggxtest::sampler().histogram(test_params(), {0, 0, 10}, 1, 65537);
        FAIL("2^16 + 1 phi bins were accepted");
    } catch (const ggxcl::InvalidArgument& e) {
        CHECK(std::string(e.what()).find("65537") != std::string::npos);  // the value; the range with it
    }
}

TEST_CASE("a range split across several samplers arrives in order with the one-sampler bits")
{
    ggxcl::Sampler a, b, c;
    std::vector<ggxcl::Sampler*> samplers = {&a, &b, &c};
    ggxcl::SampleParams p = test_params(ggxcl::Method::bounded);
    ggxcl::SampleSet whole = ggxtest::sampler().generate(p, {12, 1000, 10000}, {Field::o, Field::weight});
    std::vector<float> o(3 * 10000), w(10000);
    std::uint64_t expected_offset = 0;
    ggxcl::generate_split(samplers, p, {12, 1000, 10000}, {Field::o, Field::weight},
                          [&](const ggxcl::SampleSet& chunk, std::uint64_t offset) {
                              CHECK(offset == expected_offset);
                              expected_offset += chunk.count;
                              for (int comp = 0; comp < 3; ++comp)
                                  std::copy_n(chunk.o.data() + comp * chunk.count, chunk.count,
                                              o.data() + comp * 10000 + offset);
                              std::copy_n(chunk.weight.data(), chunk.count, w.data() + offset);
                          },
                          777);  // uneven chunks: 13 of 777 and a last of 676
    CHECK(expected_offset == 10000);
    CHECK(same_bits(o, whole.o));
    CHECK(same_bits(w, whole.weight));
    CHECK_THROWS_AS(ggxcl::generate_split(samplers, p, {12, 0, 100}, {Field::o},
                                          [](const ggxcl::SampleSet&, std::uint64_t) { throw std::runtime_error("sink"); },
                                          10),
                    std::runtime_error);
}

TEST_CASE("precise programs are built with -cl-fp32-correctly-rounded-divide-sqrt exactly where the device reports it")
{
    using ggxcl::Precision;
    using ggxcl::detail::precision_options_for;
    const std::string flag = "-cl-fp32-correctly-rounded-divide-sqrt", relaxed = "-cl-fast-relaxed-math";
    // The rule, for a device with the bit and one without.
    const cl_device_fp_config with_bit = CL_FP_ROUND_TO_NEAREST | CL_FP_INF_NAN | CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT;
    const cl_device_fp_config without_bit = CL_FP_ROUND_TO_NEAREST | CL_FP_INF_NAN | CL_FP_FMA;
    CHECK(precision_options_for(Precision::precise, with_bit) == " " + flag);
    CHECK(precision_options_for(Precision::precise, without_bit).empty());
    CHECK(precision_options_for(Precision::relaxed, with_bit) == " " + relaxed);
    CHECK(precision_options_for(Precision::relaxed, without_bit) == " " + relaxed);

    // This device: the options of the programs a Sampler builds, from source
    // (rusticl tells no options of a program loaded from the binary cache).
    const char* cache = std::getenv("GGXCL_PROGRAM_CACHE");
    const std::string saved_cache = cache ? cache : "";
    ::setenv("GGXCL_PROGRAM_CACHE", "off", 1);
    ggxcl::Sampler s;  // its own context: programs not built yet
    const cl::Device& device = s.device();
    const bool reported = (device.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>() & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) != 0;
    const std::string what = s.device_name() + (reported ? " reports" : " does not report");
    MESSAGE(what << " CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT");
    auto has = [](const std::string& options, const std::string& option) {
        return options.find(option) != std::string::npos;
    };
    for (Precision precision : ggxcl::all_precisions) {
        CAPTURE(ggxcl::precision_name(precision));
        const bool correctly_rounded = precision == Precision::precise && reported;
        CHECK(has(ggxcl::precision_options(device, precision), flag) == correctly_rounded);
        ggxcl::SampleParams p = test_params(ggxcl::Method::heitz);
        p.precision = precision;
        const ggxcl::FieldSet fields{Field::m, Field::pdf_m};
        s.warm_up(p, fields);
        const std::size_t built = s.programs_built();
        // The options are the program's key: the same program, not a new one.
        const std::string options = ggxcl::detail::build_options(
            device, ggxcl::detail::variant_of(ggxcl::detail::ProgramKind::bulk, ggxcl::normalized(p), fields.bits()));
        cl::Program program = ggxcl::ProgramCache::for_context(s.context())->get(device, "ggx_bulk.cl", options);
        CHECK(s.programs_built() == built);
        const std::string built_with = program.getBuildInfo<CL_PROGRAM_BUILD_OPTIONS>(device);
        CAPTURE(built_with);
        CHECK(has(built_with, flag) == correctly_rounded);
        CHECK(has(built_with, relaxed) == (precision == Precision::relaxed));
    }
    if (cache)
        ::setenv("GGXCL_PROGRAM_CACHE", saved_cache.c_str(), 1);
    else
        ::unsetenv("GGXCL_PROGRAM_CACHE");
}
