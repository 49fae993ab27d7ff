// sample_job.hpp - one `ggx sample` job: the samples of a range written
// chunk by chunk into a float32 .npy of shape (count, columns), with a JSON
// sidecar that records how they were made.
#pragma once

#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace ggxapp {

struct SampleJob {
    ggxcl::SampleParams params;
    double theta_degrees = 0.0, phi_degrees = 0.0;
    ggxcl::SampleRange range;
    std::vector<ggxcl::Field> fields;  // column order of the file
    std::string out;                   // path of the .npy
};

// Column names in file order, e.g. m_x, m_y, m_z, pdf_o.
std::vector<std::string> column_names(const std::vector<ggxcl::Field>& fields);

// "samples.npy" -> "samples.json".
std::string sidecar_path(const std::string& npy_path);

// Writes the .npy and its sidecar (each through a temporary file).
void run_sample_job(ggxcl::Sampler& sampler, const SampleJob& job);

} // namespace ggxapp
