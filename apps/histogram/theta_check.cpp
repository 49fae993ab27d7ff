// theta_check.cpp - a user sampler's samples in rings of equal mass in theta.
#include "theta_check.hpp"

#include <algorithm>
#include <cmath>

#include "pdf_rings.hpp"
#include "reference_bridge.hpp"
#include "report_text.hpp"
#include "user_fit_checks.hpp"

namespace ggxapp {

namespace {

constexpr int ring_count = 64;
constexpr double degrees_per_radian = 57.29577951308232;

// The kept samples in the rings, one more cell for those outside them (below the horizon with a
// weight, or m below the surface), directions that are not finite and the discarded apart.
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
            const int ring = ggxbridge::ring_of(edges, double(d.z) / length);
            ++h.counts[ring < 0 ? edges.size() - 1 : std::size_t(ring)];
        }
    }
    return h;
}

} // namespace

HistogramCheck theta_check(const ggxbridge::DirectionPdf& pdf, const ggxcl::SampleParams& params,
                           const ggxcl::SampleSet& samples, ggxcl::Field direction, double level)
{
    const std::uint64_t n = samples.count;
    const ggxbridge::PdfRings rings = ggxbridge::equal_mass_rings(pdf, params, direction, ring_count, n);
    const std::string name = "its own pdf, in theta";
    if (rings.edges.empty()) {
        HistogramCheck check;
        check.name = name;
        check.passed = false;
        check.summary = name + ": no rings (the pdf has no finite positive mass above the horizon)";
        check.numbers = {{"reason", "the pdf has no finite positive mass above the horizon"}};
        return check;
    }
    const ggxcl::Histogram counts = ring_counts(samples, direction, rings.edges);
    std::vector<double> mass = rings.mass, error = rings.error;
    mass.push_back(0.0);
    error.push_back(0.0);
    HistogramCheck check = chi_square_check(name, ggxbridge::user_histogram_fit(counts, mass, error, false), level,
                                            samples_where_zero(counts, mass));
    const double innermost = std::acos(std::min(1.0, rings.edges[rings.edges.size() - 2])) * degrees_per_radian;
    check.summary += "; " + std::to_string(mass.size() - 1) + " rings of equal mass in theta (the innermost to " +
                     readable_number(innermost) + " degrees), " + std::to_string(n) + " samples";
    check.numbers["rings"] = mass.size() - 1;
    check.numbers["innermost_ring_degrees"] = innermost;
    return check;
}

} // namespace ggxapp
