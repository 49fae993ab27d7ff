// histogram_job.hpp - one `ggx histogram` job: device-binned counts of o
// (or m) over (phi, cos theta) in bins of equal solid angle, expected counts from
// the pdf integrated over each bin in double precision (the reference), a
// chi-square test, and the files: PREFIX.observed.npy, PREFIX.expected.npy
// (float64, bins_z x bins_phi), PREFIX.json and PREFIX.png.
#pragma once

#include <future>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "user_checks.hpp"

namespace ggxapp {

struct HistogramJob {
    ggxcl::SampleParams params;
    ggxcl::Method against = ggxcl::Method::caps;  // whose pdf gives the expectation (normally params.method)
    double theta_degrees = 0.0, phi_degrees = 0.0;
    ggxcl::SampleRange range;
    int bins_z = 32, bins_phi = 64;
    ggxcl::Field direction = ggxcl::Field::o;  // o or m
    std::string prefix;
    bool png = true;
    double level = 1e-3;  // a user sampler's checks: a chi-square passes when p >= level
};

struct HistogramResult {
    double chi_square = 0, p_value = 0, samples_per_second = 0;
    int dof = 0;
    std::string png;  // path of the figure, empty when none was drawn
    // A user sampler (Method::user): chi-square against its own pdf (the result above), against
    // the distribution it claims, and its pdf_o against the pdfs recomputed from (i, o).
    std::vector<HistogramCheck> checks;
};

// The expected probability of each bin (the reference's quadrature of the
// pdf of job.against; for a user sampler, of the distribution it claims,
// none for its own), computed on threads of its own while the caller opens
// the device and the device bins.
std::future<std::vector<double>> start_expectation(const HistogramJob& job);

HistogramResult run_histogram_job(ggxcl::Backend& device, const HistogramJob& job,
                                  std::future<std::vector<double>> expectation);
// Starts the expectation itself, beside the warm-up run.
HistogramResult run_histogram_job(ggxcl::Backend& device, const HistogramJob& job);

} // namespace ggxapp
