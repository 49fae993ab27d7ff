// demo_page.hpp - `ggx demo`'s index.html: the summary's Markdown as HTML,
// then a card per method with its rotatable 3-D cloud (cloud_view.hpp), its
// chi-square verdict and speed, its histogram figure and links to its files.
#pragma once

#include <string>
#include <vector>

#include <ggxcl/sampler.hpp>

#include "histogram_job.hpp"

namespace ggxapp {

struct DemoPageMethod {
    std::string name;
    HistogramResult histogram;
    ggxcl::SampleSet cloud;  // the first samples of the method's cloud: m, o, pdf_m, pdf_o
};

// Writes `path` (three.js copied beside it); `summary_markdown` heads the page.
void write_demo_page(const std::string& path, const std::string& summary_markdown,
                     const std::vector<DemoPageMethod>& methods, ggxcl::Vec3 view);

} // namespace ggxapp
