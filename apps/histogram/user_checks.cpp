// user_checks.cpp - the bins under a device pdf, and the pdf checks of a user sampler.
#include "user_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <boost/math/quadrature/gauss.hpp>

namespace ggxapp {

namespace {

constexpr double pi = 3.14159265358979323846;

// The nodes and weights of the N-point Gauss-Legendre rule on [0, 1].
template <int N> void unit_rule(std::vector<double>& nodes, std::vector<double>& weights)
{
    using rule = boost::math::quadrature::gauss<double, N>;
    static_assert(N % 2 == 0, "even rules: every abscissa gives a pair of nodes");
    nodes.clear();
    weights.clear();
    for (std::size_t k = 0; k < rule::abscissa().size(); ++k)
        for (double sign : {-1.0, 1.0}) {
            nodes.push_back(0.5 + 0.5 * sign * rule::abscissa()[k]);
            weights.push_back(0.5 * rule::weights()[k]);
        }
}

// int over each bin of pdf(o) dz dphi (dw = dz dphi), the rule's nodes in z and in phi.
std::vector<double> bins_by_rule(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params, int bins_z, int bins_phi,
                                 const std::vector<double>& nodes, const std::vector<double>& weights)
{
    const double dz = 2.0 / bins_z, dphi = 2.0 * pi / bins_phi;
    std::vector<ggxcl::Vec3> directions;
    for (int zb = 0; zb < bins_z; ++zb)
        for (int pb = 0; pb < bins_phi; ++pb)
            for (double nz : nodes)
                for (double np : nodes) {
                    const double z = -1.0 + (zb + nz) * dz, phi = (pb + np) * dphi;
                    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                    directions.push_back({float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)});
                }
    const std::vector<float> pdfs = sampler.pdf(params, directions);
    std::vector<double> probabilities(std::size_t(bins_z) * bins_phi, 0.0);
    std::size_t k = 0;
    for (double& bin : probabilities)
        for (double wz : weights)
            for (double wp : weights)
                bin += double(pdfs[k++]) * wz * wp * dz * dphi;
    return probabilities;
}

std::string short_number(double value)
{
    std::ostringstream out;
    out.precision(3);
    out << value;
    return out.str();
}

// The relative difference of a and b (0 when both are 0).
double relative_difference(double a, double b)
{
    const double scale = std::max(std::fabs(a), std::fabs(b));
    return scale > 0.0 ? std::fabs(a - b) / scale : 0.0;
}

HistogramCheck pdf_agreement(const std::string& name, const std::vector<float>& sampled,
                             const std::vector<float>& recomputed)
{
    std::size_t with_density = 0, disagree = 0;
    double worst = 0.0;
    for (std::size_t j = 0; j < sampled.size(); ++j) {
        if (!(sampled[j] > 0.0f))
            continue;
        ++with_density;
        const double d = relative_difference(sampled[j], recomputed[j]);
        worst = std::max(worst, std::isfinite(d) ? d : 1.0);
        disagree += !(d <= 1e-3);
    }
    HistogramCheck check;
    check.name = name;
    check.passed = with_density > 0 && double(disagree) <= 1e-3 * double(with_density);
    check.summary = name + ": " + std::to_string(disagree) + " of " + std::to_string(with_density) +
                    " samples with a density differ by more than 1e-3 (relative), the largest by " +
                    short_number(worst);
    return check;
}

} // namespace

std::vector<double> pdf_bin_probabilities(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params, int bins_z,
                                          int bins_phi, double& quadrature_error)
{
    std::vector<double> nodes, weights;
    unit_rule<8>(nodes, weights);
    const std::vector<double> coarse = bins_by_rule(sampler, params, bins_z, bins_phi, nodes, weights);
    unit_rule<16>(nodes, weights);
    std::vector<double> fine = bins_by_rule(sampler, params, bins_z, bins_phi, nodes, weights);
    quadrature_error = 0.0;
    for (std::size_t b = 0; b < fine.size(); ++b)
        quadrature_error += std::fabs(fine[b] - coarse[b]);
    return fine;
}

HistogramCheck pdf_integral_check(const std::vector<double>& probabilities, double quadrature_error)
{
    double total = 0.0;
    for (double p : probabilities)
        total += p;
    const double allowed = 1e-3 + 10.0 * quadrature_error;
    HistogramCheck check;
    check.name = "pdf integrates to 1";
    check.passed = std::fabs(total - 1.0) <= allowed;
    check.summary = check.name + ": " + short_number(total) + " over the sphere (allowed: 1 +- " +
                    short_number(allowed) + ")";
    return check;
}

bool claimed_method(ggxcl::Distribution distribution, ggxcl::Method& method)
{
    if (distribution == ggxcl::Distribution::own)
        return false;
    method = distribution == ggxcl::Distribution::vndf ? ggxcl::Method::heitz : ggxcl::Method::ndf;
    return true;
}

std::vector<HistogramCheck> pdf_checks(ggxcl::Sampler& sampler, const ggxcl::SampleParams& params,
                                       const ggxcl::SampleRange& range, const ggxcl::Method* claimed)
{
    const ggxcl::SampleSet samples = sampler.generate(params, range, {ggxcl::Field::o, ggxcl::Field::pdf_o});
    std::vector<ggxcl::Vec3> directions(range.count);
    for (std::size_t j = 0; j < directions.size(); ++j)
        directions[j] = samples.o_at(j);
    std::vector<HistogramCheck> checks = {
        pdf_agreement("pdf from (i, o)", samples.pdf_o, sampler.pdf(params, directions))};
    if (claimed) {
        ggxcl::SampleParams theirs = params;
        theirs.method = *claimed;
        theirs.user_sampler = nullptr;
        const char* family = *claimed == ggxcl::Method::ndf ? "ndf" : "vndf";
        checks.push_back(pdf_agreement(std::string("pdf of the claimed ") + family, samples.pdf_o,
                                       sampler.pdf(theirs, directions)));
    }
    return checks;
}

} // namespace ggxapp
