// sample_job.hpp - one `ggx sample` job: the samples of a range written
// chunk by chunk into a .npy, .csv or .ply (see sample_writer.hpp), with a
// JSON sidecar that records how they were made.
#pragma once

#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>
#include <nlohmann/json.hpp>

#include "sample_writer.hpp"

namespace ggxapp {

struct SampleJob {
    ggxcl::SampleParams params;
    double theta_degrees = 0.0, phi_degrees = 0.0;
    ggxcl::SampleRange range;
    std::vector<ggxcl::Field> fields;  // column order of the file; for .ply a direction and its pdf
    std::string out;                   // output path
    Format format = Format::npy;
    ggxcl::PerSampleInputs per_sample;  // the caller's uniforms (one device only), else empty
    std::string uniforms_file;          // where they were read from, for the sidecar
};

// What every sidecar and summary records of how samples were drawn: method,
// roughness, precision, view (angles and vector), normal for caps-iso,
// seed and range, sequence and its generator, and library version.
nlohmann::json describe_sampling(const ggxcl::SampleParams& params, double theta_degrees, double phi_degrees,
                                 const ggxcl::SampleRange& range);

// Column names in file order, e.g. m_x, m_y, m_z, pdf_o.
std::vector<std::string> column_names(const std::vector<ggxcl::Field>& fields, bool dielectric = false);

// For a .ply: the direction the --fields list names (o by default) and its pdf.
std::vector<ggxcl::Field> ply_fields(const std::vector<ggxcl::Field>& requested);

// "samples.npy" -> "samples.json".
std::string sidecar_path(const std::string& npy_path);

// Writes the samples and their sidecar (each through a temporary file; the
// sidecar's "api" says which API and shader language drew them).
void run_sample_job(ggxcl::Backend& device, const SampleJob& job);

// The same with the range split across several OpenCL devices (one sampler
// each, ggxcl::generate_split), giving the same bits as one device of the same type.
void run_split_sample_job(const std::vector<ggxcl::Sampler*>& samplers, const SampleJob& job);

} // namespace ggxapp
