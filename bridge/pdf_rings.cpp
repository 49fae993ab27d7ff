// pdf_rings.cpp - rings of equal mass in theta under a device pdf.
#include "pdf_rings.hpp"

#include <algorithm>
#include <cmath>

#include "reference_bridge.hpp"

namespace ggxbridge {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr int fine_rings = 512, fine_phi = 4, ring_phi = 16;
constexpr std::size_t ring_budget = 2u << 20;  // pdf evaluations refining the rings

// Each ring's sum over the phi bins of one BinIntegrals vector.
std::vector<double> per_ring(const std::vector<double>& bins, int phi_bins)
{
    std::vector<double> out(bins.size() / std::size_t(phi_bins), 0.0);
    for (std::size_t b = 0; b < bins.size(); ++b)
        out[b / std::size_t(phi_bins)] += bins[b];
    return out;
}

// The edges where the cumulative mass over `fine` (rings between fine_edges, ascending) crosses
// k / rings of its total, linear within a fine ring; the first edge the lower one of the first fine
// ring with mass, so that a support that begins inside a wide first ring (a lobe that starts at
// cos theta = -iz, for a view below the horizon) is integrated where it is, not missed.
std::vector<double> equal_mass_edges(const std::vector<double>& fine_edges, const std::vector<double>& fine,
                                     int rings)
{
    double total = 0.0;
    for (double m : fine)
        total += std::max(m, 0.0);
    if (!(total > 0.0) || !std::isfinite(total))
        return {};
    std::size_t first = 0;
    while (first + 1 < fine.size() && !(fine[first] > 0.0))
        ++first;
    std::vector<double> edges = {fine_edges[first]};
    double below = 0.0;
    int next = 1;
    for (std::size_t k = 0; k < fine.size() && next < rings; ++k) {
        const double m = std::max(fine[k], 0.0);
        while (next < rings && below + m >= total * next / rings) {
            const double t = m > 0.0 ? (total * next / rings - below) / m : 0.0;
            const double z = fine_edges[k] + t * (fine_edges[k + 1] - fine_edges[k]);
            if (z > edges.back())
                edges.push_back(z);
            ++next;
        }
        below += m;
    }
    edges.push_back(fine_edges.back());
    return edges;
}

} // namespace

PdfRings equal_mass_rings(const DirectionPdf& pdf, const ggxcl::SampleParams& params, ggxcl::Field direction,
                          int rings, std::uint64_t samples)
{
    BinRequest marginal{fine_rings, fine_phi, direction, samples, nullptr};
    for (int k = 0; k <= fine_rings; ++k)  // equal steps in theta from the horizon to the pole
        marginal.z_edges.push_back(std::cos(0.5 * pi * (1.0 - double(k) / fine_rings)));
    marginal.z_edges.front() = 0.0;
    marginal.refinement_budget = 0;
    const std::vector<double> fine = per_ring(integrate_bins(pdf, params, marginal).kept, fine_phi);
    PdfRings out;
    out.edges = equal_mass_edges(marginal.z_edges, fine, rings);
    if (out.edges.size() < 3)
        return {};
    BinRequest exact{int(out.edges.size()) - 1, ring_phi, direction, samples, nullptr};
    exact.z_edges = out.edges;
    exact.refinement_budget = ring_budget;
    const BinIntegrals integrals = integrate_bins(pdf, params, exact);
    out.mass = per_ring(integrals.kept, ring_phi);
    out.error = per_ring(integrals.error, ring_phi);
    return out;
}

int ring_of(const std::vector<double>& edges, double z)
{
    if (edges.size() < 2 || !(z >= edges.front()) || z > edges.back())
        return -1;
    const auto above = std::upper_bound(edges.begin(), edges.end(), z);
    return int(std::min<std::ptrdiff_t>(above - edges.begin() - 1, std::ptrdiff_t(edges.size()) - 2));
}

ggxcl::Histogram ring_counts(const ggxcl::SampleSet& samples, ggxcl::Field direction, const std::vector<double>& edges)
{
    ggxcl::Histogram h;
    h.bins_z = int(edges.size());
    h.bins_phi = 1;
    h.counts.assign(edges.size(), 0);  // the rings, then the cell outside them
    for (std::size_t j = 0; j < samples.count; ++j) {
        const ggxcl::Vec3 o = samples.o_at(j), d = direction == ggxcl::Field::m ? samples.m_at(j) : o;
        if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) {
            ++h.non_finite;
        } else if (o.z <= 0.0f && samples.weight[j] == 0.0f) {
            ++h.invalid;
        } else {
            const double length = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
            const int ring = ring_of(edges, double(d.z) / length);
            ++h.counts[ring < 0 ? edges.size() - 1 : std::size_t(ring)];
        }
    }
    return h;
}

ggxref::ChiSquare ring_fit(const PdfRings& rings, const ggxcl::Histogram& counts, bool with_discarded)
{
    std::vector<double> mass = rings.mass, error = rings.error;
    mass.push_back(0.0);
    error.push_back(0.0);
    return user_histogram_fit(counts, mass, error, with_discarded);
}

} // namespace ggxbridge
