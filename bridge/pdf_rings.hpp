// pdf_rings.hpp - rings of equal mass in the polar angle under a sampler's
// pdf, to test a narrow lobe in theta where the histogram's bins of equal
// solid angle put most of it in one ring (at alpha 0.05 and V = N, 93 % of
// the lobe falls in the top one of 32): the pdf's marginal over 512 rings
// of equal width in theta (one rule each), edges where its cumulative mass crosses k / R,
// and those R rings integrated again adaptively.  Rings cover the upper
// hemisphere (o above the horizon, or m.z > 0), where samples are kept.
#pragma once

#include <cstdint>
#include <vector>

#include "pdf_bins.hpp"

namespace ggxbridge {

struct PdfRings {
    std::vector<double> edges;       // R + 1 values of cos theta, ascending, from where the mass begins to 1
    std::vector<double> mass, error;  // each ring's kept probability and its integration error
};

// R rings of equal mass under params' pdf of `direction` (o or m); no rings (empty edges) when
// the pdf has no finite positive mass above the horizon.  `samples` sets the accuracy as in
// BinRequest.
PdfRings equal_mass_rings(const DirectionPdf& pdf, const ggxcl::SampleParams& params, ggxcl::Field direction,
                          int rings, std::uint64_t samples);

// The ring of cos theta z, -1 outside [edges.front(), edges.back()].
int ring_of(const std::vector<double>& edges, double z);

} // namespace ggxbridge
