// cloud_view.cpp - a sample cloud quantized and encoded for the page.
#include "cloud_view.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "html_page.hpp"
#include "report_text.hpp"

namespace ggxapp {

namespace {

// The log10 pdf range the colours span: the 1st to 99th percentile of the densities.
struct PdfRange {
    double low = 0, high = 1;
};

PdfRange pdf_range(const std::vector<float>& pdf)
{
    std::vector<double> logs;
    for (float p : pdf)
        if (p > 0.0f && std::isfinite(p))
            logs.push_back(std::log10(double(p)));
    if (logs.empty())
        return {};
    std::sort(logs.begin(), logs.end());
    PdfRange range{logs[logs.size() / 100], logs[logs.size() - 1 - logs.size() / 100]};
    if (range.high - range.low < 1e-6)
        range.high = range.low + 1e-6;
    return range;
}

// Planar components (x plane, y plane, z plane) as interleaved int16 little-endian bytes.
std::string quantized_directions(const std::vector<float>& planes, std::uint64_t count)
{
    std::string bytes;
    bytes.reserve(6 * count);
    for (std::uint64_t j = 0; j < count; ++j)
        for (int c = 0; c < 3; ++c) {
            const float v = std::clamp(planes[c * count + j], -1.0f, 1.0f);
            const auto q = std::uint16_t(std::int16_t(std::lround(v * 32767.0f)));
            bytes += char(q & 0xff);
            bytes += char(q >> 8);
        }
    return bytes;
}

// One byte per point: 0 without density, else 1..255 over the log pdf range.
std::string pdf_shades(const std::vector<float>& pdf, const PdfRange& range)
{
    std::string bytes;
    for (float p : pdf) {
        if (!(p > 0.0f) || !std::isfinite(p)) {
            bytes += char(0);
            continue;
        }
        const double t = std::clamp((std::log10(double(p)) - range.low) / (range.high - range.low), 0.0, 1.0);
        bytes += char(1 + std::lround(t * 254.0));
    }
    return bytes;
}

std::string legend_html(const char* field, const PdfRange& range)
{
    std::ostringstream html;
    html << "<span class=\"legend-" << field << "\">pdf_" << field << " " << readable_number(std::pow(10.0, range.low))
         << " <span class=\"legend\"></span> " << readable_number(std::pow(10.0, range.high)) << " /sr</span>";
    return html.str();
}

} // namespace

std::string base64(const std::string& bytes)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t k = 0; k < bytes.size(); k += 3) {
        std::uint32_t group = std::uint32_t(std::uint8_t(bytes[k])) << 16;
        if (k + 1 < bytes.size())
            group |= std::uint32_t(std::uint8_t(bytes[k + 1])) << 8;
        if (k + 2 < bytes.size())
            group |= std::uint8_t(bytes[k + 2]);
        const std::size_t left = bytes.size() - k;       // 1, 2 or at least 3 bytes in this group
        const int written = left >= 3 ? 4 : int(left) + 1;  // digits that carry bits; '=' pads the rest
        for (int d = 0; d < 4; ++d)
            out += d < written ? digits[(group >> (18 - 6 * d)) & 63] : '=';
    }
    return out;
}

std::string cloud_figure_html(const CloudFigure& figure, const ggxcl::SampleSet& samples, ggxcl::Vec3 view)
{
    const PdfRange o_range = pdf_range(samples.pdf_o), m_range = pdf_range(samples.pdf_m);
    std::ostringstream html;
    html << "<div class=\"cloud\" id=\"" << html_escaped(figure.id) << "\">\n<h3>" << html_escaped(figure.title)
         << "</h3>\n<div class=\"view\"></div>\n<p>show <button class=\"on\" data-show=\"o\">o</button> "
         << "<button data-show=\"m\">m</button> &nbsp; " << samples.count
         << " samples; black arrow: the normal, red: the view</p>\n<p>colour: " << legend_html("o", o_range)
         << "<br>colour: " << legend_html("m", m_range) << "</p>\n<div class=\"numbers\">" << figure.numbers_html
         << "</div>\n<div class=\"files\">" << figure.files_html << "</div>\n<script>ggxCloud(\"" << figure.id
         << "\", {view: [" << view.x << ", " << view.y << ", " << view.z << "],\n o: \""
         << base64(quantized_directions(samples.o, samples.count)) << "\",\n o_colour: \""
         << base64(pdf_shades(samples.pdf_o, o_range)) << "\",\n m: \""
         << base64(quantized_directions(samples.m, samples.count)) << "\",\n m_colour: \""
         << base64(pdf_shades(samples.pdf_m, m_range)) << "\"});</script>\n</div>\n";
    return html.str();
}

} // namespace ggxapp
