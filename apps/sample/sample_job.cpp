// sample_job.cpp - streams samples from the device into the output file and
// writes the JSON sidecar.
#include "sample_job.hpp"

#include <algorithm>
#include <functional>
#include <utility>

#include <nlohmann/json.hpp>

#include "atomic_file.hpp"
#include "cli_values.hpp"
#include "progress.hpp"
#include "writer_thread.hpp"

namespace ggxapp {

namespace {

// Rows first + j of `columns` floats from one plane pointer per column: the
// column count fixed at compile time, so that each row is written whole and
// in order.
template <int columns>
void rows_from_planes(const float* const* planes, std::size_t first, std::size_t last, float* rows)
{
    const float* p[columns];
    std::copy_n(planes, columns, p);
    for (std::size_t j = first; j < last; ++j)
        for (int c = 0; c < columns; ++c)
            rows[j * columns + c] = p[c][j];
}

template <int... counts>
void rows_for(std::size_t columns, const float* const* planes, std::size_t count, float* rows,
              std::integer_sequence<int, counts...>)
{
    ((columns == counts + 1 ? rows_from_planes<counts + 1>(planes, 0, count, rows) : void()), ...);
}

// The chunk's requested fields as rows (count x columns, 1 to 12 columns), in
// `fields` order, into `rows`.
void interleave(const ggxcl::SampleView& chunk, const std::vector<ggxcl::Field>& fields, bool dielectric,
                std::size_t columns, std::vector<float>& rows)
{
    rows.resize(chunk.count * columns);
    std::vector<const float*> planes;
    for (ggxcl::Field field : fields)
        for (int c = 0; c < ggxcl::field_columns(field, dielectric); ++c)
            planes.push_back(chunk.column_source(field) + c * chunk.stride);
    rows_for(columns, planes.data(), chunk.count, rows.data(), std::make_integer_sequence<int, 12>{});
}

std::string device_names(const std::vector<ggxcl::Sampler*>& samplers)
{
    std::string names;
    for (const ggxcl::Sampler* s : samplers)
        names += (names.empty() ? "" : " + ") + s->device_name();
    return names;
}

// `device`: the device or devices that drew the samples; `api`: "opencl", or "vulkan (glsl)".
nlohmann::json sidecar(const std::string& device, const std::string& api, const SampleJob& job)
{
    nlohmann::json doc = describe_sampling(job.params, job.theta_degrees, job.phi_degrees, job.range);
    const bool dielectric = job.params.eta != 0.0f;
    doc["columns"] = column_names(job.fields, dielectric);
    doc["format"] = job.format == Format::npy ? "npy float32" : job.format == Format::csv ? "csv" : "ply binary";
    if (job.format == Format::ply)
        doc["ply"] = "vertices are the first three columns, colored by log10 of the fourth over [-2, 3]";
    doc["shape"] = {job.range.count, column_names(job.fields, dielectric).size()};
    if (!job.uniforms_file.empty()) {
        doc.erase("sequence");
        doc["generator"] = "the caller's uniforms, rows of " + job.uniforms_file;
    }
    doc["device"] = device;
    doc["api"] = api;
    return doc;
}

// Draws the job's samples through `draw`, which hands each chunk to the sink
// it is given, into the job's file and sidecar (each through a temporary file).
using DrawChunks = std::function<void(const ggxcl::ChunkViewSink& sink)>;
void write_samples(const SampleJob& job, const std::string& device, const std::string& api, const DrawChunks& draw)
{
    const bool dielectric = job.params.eta != 0.0f;
    const std::vector<std::string> names = column_names(job.fields, dielectric);
    const std::size_t columns = names.size();
    std::unique_ptr<SampleWriter> writer = make_writer(job.format, job.out, job.range.count, names);
    AtomicFile json_file(sidecar_path(job.out));  // opened now: fail before sampling if unwritable
    Progress progress(job.out, job.range.count);
    WriterThread writing(*writer);  // the file is written while the next chunk is drawn
    if (job.range.count != 0)  // a shard with no samples (--shard R/S, S > N): no rows, a sidecar
        draw([&](const ggxcl::SampleView& chunk, std::uint64_t offset) {
            std::vector<float> rows = writing.take_buffer();
            interleave(chunk, job.fields, dielectric, columns, rows);
            writing.append(std::move(rows));
            progress.advance(offset + chunk.count);
        });
    writing.finish();
    std::string text = sidecar(device, api, job).dump(2) + "\n";
    json_file.write(text.data(), text.size());
    writer->commit();
    json_file.commit();
}

} // namespace

nlohmann::json describe_sampling(const ggxcl::SampleParams& p, double theta_degrees, double phi_degrees,
                                 const ggxcl::SampleRange& range)
{
    nlohmann::json doc;
    doc["method"] = ggxcl::sampler_name(p);
    if (p.user_sampler) {
        doc["sampler_file"] = p.user_sampler->path();
        doc["sampler_key"] = p.user_sampler->key();
        doc["sampler_distribution"] = std::string(ggxcl::distribution_name(p.user_sampler->distribution()));
    }
    doc["alpha"] = {p.alpha_x, p.alpha_y};
    doc["precision"] = std::string(ggxcl::precision_name(p.precision));
    doc["theta_degrees"] = theta_degrees;
    doc["phi_degrees"] = phi_degrees;
    doc["view"] = {p.view.x, p.view.y, p.view.z};
    const bool about_normal = ggxcl::uses_normal(p);
    doc["view_space"] = about_normal ? "world" : "tangent";
    if (about_normal)
        doc["normal"] = {p.normal.x, p.normal.y, p.normal.z};
    doc["seed"] = range.seed;
    doc["first"] = range.first;
    doc["count"] = range.count;
    if (p.eta != 0.0f) {
        doc["eta"] = p.eta;
        doc["transport"] = std::string(ggxcl::transport_name(p.transport));
    }
    doc["sequence"] = std::string(ggxcl::sequence_name(p.sequence));
    doc["generator"] = ggxcl::sequence_description(p.sequence);
    doc["ggxcl_version"] = ggxcl::version();
    return doc;
}

std::vector<std::string> column_names(const std::vector<ggxcl::Field>& fields, bool dielectric)
{
    std::vector<std::string> names;
    for (ggxcl::Field field : fields) {
        std::string base(ggxcl::field_name(field));
        const int columns = ggxcl::field_columns(field, dielectric);
        if (field == ggxcl::Field::m || field == ggxcl::Field::o)
            for (const char* axis : {"_x", "_y", "_z"})
                names.push_back(base + axis);
        else if (columns > 1)
            for (int index = 1; index <= columns; ++index)
                names.push_back(base + std::to_string(index));
        else
            names.push_back(base);
    }
    return names;
}

std::vector<ggxcl::Field> ply_fields(const std::vector<ggxcl::Field>& requested)
{
    using ggxcl::Field;
    if (requested.size() == 1 && requested[0] == Field::m)
        return {Field::m, Field::pdf_m};
    if (requested.size() == 1 && requested[0] == Field::o)
        return {Field::o, Field::pdf_o};
    throw UsageError("--fields", "", "o or m for a .ply (the direction plotted, colored by its pdf)");
}

std::string sidecar_path(const std::string& npy_path)
{
    std::size_t dot = npy_path.rfind('.');
    std::size_t slash = npy_path.rfind('/');
    bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return (has_extension ? npy_path.substr(0, dot) : npy_path) + ".json";
}

void run_sample_job(ggxcl::Backend& device, const SampleJob& job)
{
    write_samples(job, device.device_name(), device.api_label(), [&](const ggxcl::ChunkViewSink& sink) {
        device.generate_chunk_views(job.params, job.range, ggxcl::FieldSet(job.fields), sink, job.per_sample);
    });
}

void run_split_sample_job(const std::vector<ggxcl::Sampler*>& samplers, const SampleJob& job)
{
    if (samplers.size() == 1)
        return run_sample_job(*samplers.front(), job);
    write_samples(job, device_names(samplers), "opencl", [&](const ggxcl::ChunkViewSink& sink) {
        ggxcl::generate_split(samplers, job.params, job.range, ggxcl::FieldSet(job.fields),
                              [&](const ggxcl::SampleSet& chunk, std::uint64_t offset) {
                                  sink(ggxcl::view_of(chunk), offset);
                              });
    });
}

} // namespace ggxapp
