// pdf_bins.cpp - the bins' probabilities under a device pdf.
#include "pdf_bins.hpp"

#include <cmath>

#include <boost/math/quadrature/gauss.hpp>

#include "reference_bridge.hpp"

namespace ggxbridge {

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
std::vector<double> bins_by_rule(const DirectionPdf& pdf, const ggxcl::SampleParams& params, int bins_z, int bins_phi,
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
    const std::vector<float> pdfs = pdf(params, directions);
    std::vector<double> probabilities(std::size_t(bins_z) * bins_phi, 0.0);
    std::size_t k = 0;
    for (double& bin : probabilities)
        for (double wz : weights)
            for (double wp : weights)
                bin += double(pdfs[k++]) * wz * wp * dz * dphi;
    return probabilities;
}

} // namespace

std::vector<double> pdf_bin_probabilities(const DirectionPdf& pdf, const ggxcl::SampleParams& params, int bins_z,
                                          int bins_phi, double& quadrature_error)
{
    std::vector<double> nodes, weights;
    unit_rule<8>(nodes, weights);
    const std::vector<double> coarse = bins_by_rule(pdf, params, bins_z, bins_phi, nodes, weights);
    unit_rule<16>(nodes, weights);
    std::vector<double> fine = bins_by_rule(pdf, params, bins_z, bins_phi, nodes, weights);
    quadrature_error = 0.0;
    for (std::size_t b = 0; b < fine.size(); ++b)
        quadrature_error += std::fabs(fine[b] - coarse[b]);
    return fine;
}

bool claimed_method(ggxcl::Distribution distribution, ggxcl::Method& method)
{
    if (distribution == ggxcl::Distribution::own)
        return false;
    method = distribution == ggxcl::Distribution::vndf ? ggxcl::Method::heitz : ggxcl::Method::ndf;
    return true;
}

std::vector<double> claimed_bin_probabilities(const ggxcl::SampleParams& params, int bins_z, int bins_phi)
{
    ggxcl::SampleParams theirs = ggxcl::normalized(params);
    if (!claimed_method(params.user_sampler->distribution(), theirs.method))
        return {};
    theirs.user_sampler = nullptr;
    return bin_probabilities(theirs.method, theirs, bins_z, bins_phi, ggxcl::Field::o);
}

} // namespace ggxbridge
