// pdf_bins.hpp - a histogram's expectation from a sampler's pdf on the
// device (Backend::pdf), for samplers the reference does not know (a user
// sampler): each bin of equal solid angle (the device histogram's, over
// cos theta in [-1, 1] and phi) integrated adaptively in (cos theta, phi),
// where dw = d(cos theta) dphi, with an error estimate per bin.  Used by
// `ggx histogram` and the Python Sampler.histogram.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <ggxcl/ggxcl.hpp>

#include "ggx_stats.hpp"

namespace ggxbridge {

// The pdf of each direction under a request: a back end's (Backend::pdf) or the reference's.
using DirectionPdf = std::function<std::vector<float>(const ggxcl::SampleParams&, const std::vector<ggxcl::Vec3>&)>;
DirectionPdf direction_pdf(ggxcl::Backend& backend);

// The double-precision reference's pdf of o (ggxref::pdf_o) of a built-in method, as a DirectionPdf
// on the host.
DirectionPdf reference_direction_pdf(ggxcl::Method method);

// What a histogram bins and how finely its expectation must hold.
struct BinRequest {
    int bins_z = 32, bins_phi = 64;
    ggxcl::Field direction = ggxcl::Field::o;  // o, or m (density 4 |i.m| pdf_o(reflect(i, m)), m.z > 0)
    std::uint64_t samples = 1000000;           // the histogram's count: each bin's error is held well
                                               // below its count's Poisson noise
    // The histogram's counts, when known: a bin with samples where no node found a density is
    // subdivided until one does (a thin sliver of support between nodes).
    const std::vector<std::uint64_t>* observed = nullptr;
    // Edges in cos theta, ascending, when the bins are not bins_z equal steps over [-1, 1] (rings
    // of equal mass: pdf_rings.hpp); bins_z is then their count.
    std::vector<double> z_edges = {};
    // pdf evaluations beyond the first pass, all rounds; 0: one rule per bin, no error estimate.
    std::size_t refinement_budget = 12u << 20;
};

// Each bin's probability under a pdf of o, integrated adaptively: each region gets the 8x8-point
// Gauss-Legendre rule and the same rule on its four quarters; a region whose two estimates differ
// by more than its share of the bin's target is quartered, round after round (within a budget of
// pdf evaluations), which refines near singular points and support edges alone.
struct BinIntegrals {
    // `kept`: the density where o is above the horizon (what a conductor's sampler keeps: the rest,
    // o below with weight 0, is discarded); `whole`: the density wherever o goes; `error`: the
    // larger estimated error of the two (the finer estimate's change from the coarser).
    std::vector<double> kept, whole, error;
    std::size_t evaluations = 0;  // pdf evaluations, all rounds
    int deepest = 0;              // the most times a bin was halved in each axis
    double kept_total() const;
    double whole_total() const;
    double error_total() const;
};

BinIntegrals integrate_bins(const DirectionPdf& pdf, const ggxcl::SampleParams& params, const BinRequest& request);

// The built-in method whose pdf is the claimed distribution's (heitz for vndf, ndf for ndf); false
// for a density of its own.
bool claimed_method(ggxcl::Distribution distribution, ggxcl::Method& method);

// The bins' probabilities under the distribution params' user sampler claims (the reference's
// quadrature, bin_probabilities of reference_bridge.hpp, over the whole sphere); empty for a
// density of its own.
std::vector<double> claimed_bin_probabilities(const ggxcl::SampleParams& params, int bins_z, int bins_phi);

// The claimed distribution's probability of each bin's kept samples (o above the horizon), from
// its whole-sphere bins of o (`whole`, the reference's quadrature; bins_z even), or for bins of m
// by integrating the reference's pdf; `below`: its mass below the horizon (what a sampler of it
// discards).
struct ClaimedBins {
    std::vector<double> kept;
    double below = 0.0;
};
ClaimedBins claimed_bins(const ggxcl::SampleParams& params, ggxcl::Method claimed, const BinRequest& request,
                         const std::vector<double>& whole);

// What a user sampler's histogram is tested against, computed once for every front end (`ggx
// histogram`, Python's Sampler.histogram): its pdf's integrals over the bins and their fit (kept
// samples, shape alone), and where it claims a distribution, that distribution's kept bins and
// their fit (discarded samples one more category).  `claimed_whole`: the claimed distribution's
// bins of o over the sphere (claimed_bin_probabilities; unused for bins of m).
struct UserFits {
    BinIntegrals own;
    ggxref::ChiSquare own_fit{};
    bool claims = false;
    ggxcl::Method claimed_method = ggxcl::Method::heitz;
    ClaimedBins claimed;
    ggxref::ChiSquare claimed_fit{};
};
UserFits user_fits(const DirectionPdf& pdf, const ggxcl::SampleParams& params, const ggxcl::Histogram& counts,
                   const BinRequest& request, const std::vector<double>& claimed_whole);

} // namespace ggxbridge
