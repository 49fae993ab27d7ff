// pdf_bins.hpp - a histogram's expectation from a sampler's pdf on the
// device (Sampler::pdf or VulkanSampler::pdf), for samplers the reference does not know (a user
// sampler): each bin of equal solid angle (the device histogram's, over
// cos theta in [-1, 1] and phi) integrated by Gauss-Legendre rules in
// (cos theta, phi), where dw = d(cos theta) dphi.  Used by `ggx histogram`
// and the Python Sampler.histogram.
#pragma once

#include <functional>
#include <vector>

#include <ggxcl/ggxcl.hpp>

namespace ggxbridge {

// The pdf of each direction under a request, on a device: Sampler::pdf or VulkanSampler::pdf.
using DirectionPdf = std::function<std::vector<float>(const ggxcl::SampleParams&, const std::vector<ggxcl::Vec3>&)>;

template <class Api>
DirectionPdf direction_pdf(Api& sampler)
{
    return [&sampler](const ggxcl::SampleParams& p, const std::vector<ggxcl::Vec3>& o) { return sampler.pdf(p, o); };
}

// Each bin's probability under params' pdf (over the whole sphere) by the 16x16-point rule, with
// the change from the 8x8-point rule's, |fine - coarse| summed over the bins, in `quadrature_error`.
std::vector<double> pdf_bin_probabilities(const DirectionPdf& pdf, const ggxcl::SampleParams& params, int bins_z,
                                          int bins_phi, double& quadrature_error);

// The built-in method whose pdf is the claimed distribution's (heitz for vndf, ndf for ndf); false
// for a density of its own.
bool claimed_method(ggxcl::Distribution distribution, ggxcl::Method& method);

// The bins' probabilities under the distribution params' user sampler claims (the reference's
// quadrature, bin_probabilities of reference_bridge.hpp); empty for a density of its own.
std::vector<double> claimed_bin_probabilities(const ggxcl::SampleParams& params, int bins_z, int bins_phi);

} // namespace ggxbridge
