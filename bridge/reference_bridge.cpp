// reference_bridge.cpp - library types to reference types and back.
#include "reference_bridge.hpp"

#include "ggx_quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace ggxbridge {

namespace {

static_assert(ggxref::all_methods.size() == ggxcl::all_methods.size(), "the same methods on both sides");

// Both enums are made from the one list of methods (GGX_METHOD_LIST) with its ids, so a
// method's id maps it.
std::size_t method_index(int id)
{
    if (id < 0 || std::size_t(id) >= ggxcl::all_methods.size())
        throw std::logic_error("not a method id: " + std::to_string(id));
    return std::size_t(id);
}

} // namespace

ggxref::Method reference_method(ggxcl::Method method)
{
    return ggxref::all_methods[method_index(static_cast<int>(method))];
}

ggxcl::Method library_method(ggxref::Method method)
{
    return ggxcl::all_methods[method_index(static_cast<int>(method))];
}

ggxref::Vec3 reference_direction(const ggxcl::Vec3& d)
{
    return ggxref::normalize({d.x, d.y, d.z});
}

ggxref::Params reference_params(const ggxcl::SampleParams& p)
{
    ggxref::Params r;
    r.ax = p.alpha_x;
    r.ay = p.alpha_y;
    r.i = reference_direction(p.view);
    r.n = reference_direction(p.normal);
    return r;
}

ggxcl::SampleParams library_params(ggxref::Method method, const ggxref::Params& p, ggxcl::Precision precision)
{
    ggxcl::SampleParams out;
    out.precision = precision;
    out.method = library_method(method);
    out.alpha_x = float(p.ax);
    out.alpha_y = float(p.ay);
    out.view = {float(p.i.x), float(p.i.y), float(p.i.z)};
    out.normal = {float(p.n.x), float(p.n.y), float(p.n.z)};
    return out;
}

std::vector<double> bin_probabilities(ggxcl::Method method, const ggxcl::SampleParams& params, int bins_z,
                                      int bins_phi, ggxcl::Field direction)
{
    const ggxref::Method m = reference_method(method);
    const ggxref::Params p = reference_params(params);
    if (params.eta != 0.0f) {
        if (direction != ggxcl::Field::o)
            throw ggxcl::InvalidArgument("direction", std::string(ggxcl::field_name(direction)),
                                         "o for a dielectric (eta): the directions drawn over the whole sphere");
        return ggxref::dielectric_bin_probabilities(m, p, params.eta, bins_z, bins_phi);
    }
    return direction == ggxcl::Field::m ? ggxref::bin_probabilities_m(m, p, bins_z, bins_phi)
                                        : ggxref::bin_probabilities(m, p, bins_z, bins_phi);
}

ggxref::ChiSquare histogram_fit(const ggxcl::Histogram& histogram, const std::vector<double>& probabilities,
                                bool dielectric)
{
    if (!dielectric)
        return ggxref::chi_square_gof_float(histogram.counts, probabilities);
    std::vector<std::uint64_t> counts = histogram.counts;
    std::vector<double> expected = probabilities;
    counts.push_back(histogram.invalid);
    expected.push_back(std::max(0.0, 1.0 - std::accumulate(probabilities.begin(), probabilities.end(), 0.0)));
    return ggxref::chi_square_gof_float(counts, expected);
}

ggxref::ChiSquare user_histogram_fit(const ggxcl::Histogram& counts, const std::vector<double>& kept,
                                     const std::vector<double>& error, bool with_discarded)
{
    std::vector<std::uint64_t> observed = counts.counts;
    std::vector<double> expected = kept, errors = error.empty() ? std::vector<double>(kept.size(), 0.0) : error;
    const double total = std::accumulate(kept.begin(), kept.end(), 0.0);
    if (with_discarded) {  // discarded: what the bins leave of 1
        observed.push_back(counts.invalid);
        expected.push_back(std::isfinite(total) ? std::max(0.0, 1.0 - total) : total);
        errors.push_back(std::accumulate(error.begin(), error.end(), 0.0));
    }
    observed.push_back(counts.non_finite);  // no pdf expects a direction that is not finite
    expected.push_back(0.0);
    errors.push_back(0.0);
    return ggxref::chi_square_gof_float(observed, expected, errors);
}

} // namespace ggxbridge
