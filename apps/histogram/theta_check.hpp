// theta_check.hpp - `ggx histogram --sampler`'s test of a lobe's width: the
// kept samples' polar angle against 64 rings of equal mass under the user's
// own pdf (bridge/pdf_rings.hpp), where the histogram's bins of equal solid
// angle would put a narrow lobe in one ring.
#pragma once

#include <ggxcl/ggxcl.hpp>

#include "user_checks.hpp"

namespace ggxapp {

// `samples` (judged_fields; o, or m, binned), discarded ones left out, against the rings; a
// chi-square check named "its own pdf, in theta".
HistogramCheck theta_check(const ggxbridge::DirectionPdf& pdf, const ggxcl::SampleParams& params,
                           const ggxcl::SampleSet& samples, ggxcl::Field direction, double level);

} // namespace ggxapp
