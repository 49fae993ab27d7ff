// sample_agreement.hpp - samples drawn on Vulkan against OpenCL's from the
// same uniforms, sample by sample: the angle of m and of o, the relative
// error of pdf_o and, where given, of a recomputed pdf; the bounds of the
// shader suites (issue 41: m and o 99% <= 1e-5 rad, max <= 2e-3; pdf
// relative 99% <= 1e-4) checked by check_agreement_bounds.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace ggxvk {

struct Agreement {
    double angle_99 = 0, angle_max = 0, pdf_99 = 0, recomputed_pdf_99 = 0;
    std::size_t non_finite = 0;  // of the tested side's o, pdf_o, weight and recomputed pdf
};

// Every sample of `tested` against `opencl` (both with m, o, pdf_o, weight);
// `tested_pdf` and `opencl_pdf`, when not empty, the pdf function's values at
// the tested side's directions.
Agreement sample_agreement(const ggxcl::SampleSet& tested, const ggxcl::SampleSet& opencl,
                           const std::vector<float>& tested_pdf = {}, const std::vector<float>& opencl_pdf = {});

// The largest of each measure.
Agreement worst_of(const Agreement& a, const Agreement& b);
std::string describe(const Agreement& a);

// doctest CHECKs of the bounds, with `label` and the measures as context.
void check_agreement_bounds(const Agreement& a, const std::string& label);

} // namespace ggxvk
