// c_host.cpp - the C API's calls into host memory (generate, pdf, eval,
// furnace), its names and versions, and what the caller's own kernels need
// (the device headers' directory, the library's build options).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "c_api/c_handles.hpp"
#include "c_api/c_params.hpp"
#include "c_api/c_status.hpp"
#include "ggxcl/error.hpp"
#include "ggxcl/method.hpp"
#include "ggxcl/user_kernels.hpp"
#include "ggxcl/version.hpp"

using namespace ggxcl::capi;
using ggxcl::Field;

namespace {

std::vector<ggxcl::Vec3> planar_directions(std::size_t count, const float* directions)
{
    if (count > 0)
        non_null(directions, "directions");
    std::vector<ggxcl::Vec3> out(count);
    for (std::size_t j = 0; j < count; ++j)
        out[j] = {directions[j], directions[count + j], directions[2 * count + j]};
    return out;
}

ggxcl_status of_directions(ggxcl_sampler* sampler, const ggxcl_params* params, size_t count, const float* directions,
                           float* out, const char* out_name, bool eval)
{
    return guarded([&] {
        ggxcl::Backend& s = *require(sampler, "sampler").backend;
        const ggxcl::SampleParams p = to_params(params);
        const std::vector<ggxcl::Vec3> dirs = planar_directions(count, directions);
        if (count > 0)
            non_null(out, out_name);
        const std::vector<float> values = eval ? s.eval(p, dirs) : s.pdf(p, dirs);
        std::copy(values.begin(), values.end(), out);
    });
}

} // namespace

extern "C" {

const char* ggxcl_version(void) { return ggxcl::version(); }

void ggxcl_version_numbers(int* major, int* minor, int* patch)
{
    int numbers[3] = {0, 0, 0};
    std::sscanf(ggxcl::version(), "%d.%d.%d", &numbers[0], &numbers[1], &numbers[2]);
    if (major)
        *major = numbers[0];
    if (minor)
        *minor = numbers[1];
    if (patch)
        *patch = numbers[2];
}

const char* ggxcl_method_name(ggxcl_method method)
{
    if (method == GGXCL_METHOD_USER)
        return ggxcl::method_name(ggxcl::Method::user).data();
    if (method < 0 || method >= GGXCL_METHOD_COUNT)
        return nullptr;
    return ggxcl::method_name(ggxcl::all_methods[static_cast<std::size_t>(method)]).data();
}

ggxcl_status ggxcl_parse_method(const char* name, ggxcl_method* method)
{
    return guarded([&] {
        ggxcl_method& out = require(method, "method");
        out = static_cast<ggxcl_method>(ggxcl::parse_method(non_null(name, "name")));
    });
}

ggxcl_status ggxcl_generate(ggxcl_sampler* sampler, const ggxcl_params* params, const ggxcl_range* range,
                            unsigned fields, const ggxcl_host_outputs* outputs)
{
    return guarded([&] {
        ggxcl::Backend& s = *require(sampler, "sampler").backend;
        const ggxcl::SampleParams p = to_params(params);
        const ggxcl::SampleRange r = to_range(range);
        const ggxcl::FieldSet wanted = to_fields(fields);
        const ggxcl_host_outputs& out = require(outputs, "outputs");
        for (Field field : ggxcl::all_fields)
            if (wanted.has(field))
                non_null(output_of(out, field), ("outputs." + std::string(ggxcl::field_name(field))).c_str());
        // Each chunk's planes straight into the caller's arrays (planes range.count apart).
        s.generate_chunk_views(p, r, wanted, [&](const ggxcl::SampleView& chunk, std::uint64_t offset) {
            for (Field field : ggxcl::all_fields) {
                if (!wanted.has(field))
                    continue;
                const float* from = chunk.column_source(field);
                float* to = output_of(out, field);
                for (int c = 0; c < ggxcl::field_columns(field, p.eta != 0.0f); ++c)
                    std::memcpy(to + c * r.count + offset, from + c * chunk.stride, chunk.count * sizeof(float));
            }
        });
    });
}

ggxcl_status ggxcl_pdf(ggxcl_sampler* sampler, const ggxcl_params* params, size_t count, const float* directions,
                       float* pdfs)
{
    return of_directions(sampler, params, count, directions, pdfs, "pdfs", false);
}

ggxcl_status ggxcl_eval(ggxcl_sampler* sampler, const ggxcl_params* params, size_t count, const float* directions,
                        float* values)
{
    return of_directions(sampler, params, count, directions, values, "values", true);
}

ggxcl_status ggxcl_furnace(ggxcl_sampler* sampler, const ggxcl_params* params, const ggxcl_range* range,
                           ggxcl_furnace_sums* sums)
{
    return guarded([&] {
        ggxcl::Backend& s = *require(sampler, "sampler").backend;
        const ggxcl::SampleParams p = to_params(params);
        const ggxcl::SampleRange r = to_range(range);
        ggxcl_furnace_sums& out = require(sums, "sums");
        const ggxcl::FurnaceSums f = s.furnace(p, r);
        out = {f.count, f.sum, f.sum_of_squares, f.reflected_sum, f.mean(), f.variance(), f.reflectance(),
               f.transmittance()};
    });
}

ggxcl_status ggxcl_histogram(ggxcl_sampler* sampler, const ggxcl_params* params, const ggxcl_range* range,
                             int bins_z, int bins_phi, ggxcl_field direction, uint64_t* counts, uint64_t* non_finite,
                             uint64_t* invalid)
{
    return guarded([&] {
        ggxcl::Backend& s = *require(sampler, "sampler").backend;
        const ggxcl::Histogram h =
            s.histogram(to_params(params), to_range(range), bins_z, bins_phi, to_field(direction, "direction"));
        std::copy(h.counts.begin(), h.counts.end(), non_null(counts, "counts"));
        *non_null(non_finite, "non_finite") = h.non_finite;
        *non_null(invalid, "invalid") = h.invalid;
    });
}

ggxcl_status ggxcl_device_include_dir(const char** directory)
{
    return guarded([&] {
        const char*& out = require(directory, "directory");
        static const std::string dir = ggxcl::device_include_dir();  // one per process
        out = dir.c_str();
    });
}

ggxcl_status ggxcl_build_options(const ggxcl_sampler* sampler, ggxcl_precision precision, char* options, size_t size,
                                 size_t* needed)
{
    return guarded([&] {
        const ggxcl::Sampler& s = opencl_of(sampler, "ggxcl_build_options");
        const std::string text = ggxcl::device_include_option() + ggxcl::device_options(s.device()) +
                                 ggxcl::precision_options(s.device(), to_precision(precision, "precision"));
        if (needed)
            *needed = text.size() + 1;
        if (!options)
            return;
        if (size < text.size() + 1)
            throw ggxcl::InvalidArgument("size", std::to_string(size),
                                         "at least " + std::to_string(text.size() + 1) + " bytes (see needed)");
        std::memcpy(options, text.c_str(), text.size() + 1);
    });
}

} // extern "C"
