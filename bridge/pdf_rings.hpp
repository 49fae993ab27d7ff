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

// The kept samples' `direction` (o, or m) counted in the rings of `edges`, one more cell for those outside
// them (above the horizon below where the mass begins, or below the horizon with a weight); directions
// that are not finite and the discarded (o below the horizon with weight 0) apart.  `samples` holds o,
// the weight and, for m, m.
ggxcl::Histogram ring_counts(const ggxcl::SampleSet& samples, ggxcl::Field direction, const std::vector<double>& edges);

// The chi-square of ring_counts against `rings`' masses (the outside cell expecting nothing): of the kept
// samples' shape, or `with_discarded` with the discarded expecting what the rings leave of 1 (a pdf that
// integrates to 1 over the sphere; reference_bridge.hpp: user_histogram_fit).
ggxref::ChiSquare ring_fit(const PdfRings& rings, const ggxcl::Histogram& counts, bool with_discarded);

} // namespace ggxbridge
