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
    const ggxcl::Histogram counts = ggxbridge::ring_counts(samples, direction, rings.edges);
    std::vector<double> mass = rings.mass;
    mass.push_back(0.0);
    HistogramCheck check = chi_square_check(name, ggxbridge::ring_fit(rings, counts, false), level,
                                            samples_where_zero(counts, mass));
    const double innermost = std::acos(std::min(1.0, rings.edges[rings.edges.size() - 2])) * degrees_per_radian;
    check.summary += "; " + std::to_string(mass.size() - 1) + " rings of equal mass in theta (the innermost to " +
                     readable_number(innermost) + " degrees), " + std::to_string(n) + " samples";
    check.numbers["rings"] = mass.size() - 1;
    check.numbers["innermost_ring_degrees"] = innermost;
    return check;
}

} // namespace ggxapp
