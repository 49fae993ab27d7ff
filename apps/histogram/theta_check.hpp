// theta_check.hpp - `ggx histogram --sampler`'s test of a lobe's width: the
// kept samples' polar angle against 64 rings of equal mass under the user's
// own pdf (bridge/pdf_rings.hpp), where the histogram's bins of equal solid
// angle would put a narrow lobe in one ring.
#pragma once

#include <ggxcl/ggxcl.hpp>

#include "user_checks.hpp"

namespace ggxapp {

// The first 2^20 samples of `range` (o, or m), discarded ones left out, against the rings; a
// chi-square check named "its own pdf, in theta".
HistogramCheck theta_check(const PdfDevice& device, const ggxcl::SampleParams& params, const ggxcl::SampleRange& range,
                           ggxcl::Field direction, double level);

} // namespace ggxapp
