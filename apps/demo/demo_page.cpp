// demo_page.cpp - `ggx demo`'s page: summary, then one card per method.
#include "demo_page.hpp"

#include <filesystem>
#include <sstream>

#include "cloud_view.hpp"
#include "html_page.hpp"
#include "report_text.hpp"

namespace ggxapp {

namespace {

std::string verdict_html(const HistogramResult& h)
{
    std::ostringstream html;
    html << "chi-square " << readable_number(h.chi_square, 4) << " on " << h.dof << " degrees of freedom: <b>p = "
         << readable_number(h.p_value) << "</b> &middot; " << rate_text(h.samples_per_second, "samples/s")
         << " (sampling and binning on the device)";
    if (!h.png.empty()) {
        const std::string png = html_escaped(std::filesystem::path(h.png).filename().string());
        html << "<br><a href=\"" << png << "\"><img alt=\"histogram: observed, expected, residuals\" src=\"" << png
             << "\"></a>";
    }
    return html.str();
}

std::string files_html(const std::string& name)
{
    std::ostringstream html;
    html << "files:";
    for (const char* suffix : {".npy", ".json", ".ply", ".hist.json", ".hist.observed.npy", ".hist.expected.npy"}) {
        const std::string file = html_escaped(name + suffix);
        html << " <a href=\"" << file << "\">" << file << "</a>";
    }
    return html.str();
}

} // namespace

void write_demo_page(const std::string& path, const std::string& summary_markdown,
                     const std::vector<DemoPageMethod>& methods, ggxcl::Vec3 view)
{
    std::ostringstream body;
    body << markdown_to_html(summary_markdown)
         << "<h2>The samples</h2>\n<p>Drag to turn a cloud, scroll to zoom. Each point is a sampled direction on the "
            "unit sphere, coloured by its density (log scale); <b>o</b> shows the reflected (or refracted) "
            "directions, <b>m</b> the microfacet normals.</p>\n<div class=\"clouds\">\n";
    for (const DemoPageMethod& method : methods)
        body << cloud_figure_html({"cloud-" + method.name, method.name, verdict_html(method.histogram),
                                   files_html(method.name)},
                                  method.cloud, view);
    body << "</div>\n";
    write_html_page(path, {"ggx demo", body.str(), true});
}

} // namespace ggxapp
