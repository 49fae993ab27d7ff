// cloud_view.hpp - one method's sample cloud on a report page: the first
// `count` samples' o and m, quantized (int16 per component, one byte of
// log pdf per point) and base64-encoded into a call of cloud_view.js's
// ggxCloud, about 10 bytes of page per direction.
#pragma once

#include <cstdint>
#include <string>

#include <ggxcl/sampler.hpp>

namespace ggxapp {

struct CloudFigure {
    std::string id;            // the element's id, unique on the page
    std::string title;         // the method's name
    std::string numbers_html;  // what is said under the view (p-value, speed)
    std::string files_html;    // links to the method's files
};

// The figure's HTML: the view, the o/m switch, the colour legend with the
// pdf range, then numbers_html and files_html.  `samples` holds m, o, pdf_m
// and pdf_o; points without density (pdf 0: the fallback, no sample) are
// drawn grey.  `view` is the direction drawn as the red arrow.
std::string cloud_figure_html(const CloudFigure& figure, const ggxcl::SampleSet& samples, ggxcl::Vec3 view);

// Bytes as base64 (RFC 4648, padded), as the page's atob() reads them.
std::string base64(const std::string& bytes);

} // namespace ggxapp
