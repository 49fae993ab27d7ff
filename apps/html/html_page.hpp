// html_page.hpp - the report pages that `ggx demo`, `bench`, `stress` and
// `converge` write beside their Markdown: one self-contained HTML file that
// opens offline from the file system (its style and scripts inlined; for
// 3-D clouds, three.js copied beside it into three/), the Markdown turned
// into HTML by cmark-gfm (GitHub's CommonMark with tables).
#pragma once

#include <string>

namespace ggxapp {

// The Markdown `markdown` as HTML (tables included; raw HTML passes through).
std::string markdown_to_html(const std::string& markdown);

// Escapes &, <, >, " for text and attribute values.
std::string html_escaped(const std::string& text);

struct HtmlPage {
    std::string title;
    std::string body;     // HTML
    bool clouds = false;  // loads three.js and the cloud views (cloud_view.hpp)
};

// Writes `page` to `path` through a temporary file; with clouds, first
// copies three.js beside it (copy_three_js).  Throws std::runtime_error
// naming what is missing.
void write_html_page(const std::string& path, const HtmlPage& page);

// Writes a report page from its Markdown: title from the first heading.
void write_markdown_page(const std::string& path, const std::string& markdown);

// Copies three.js r111's classic build, its OrbitControls and its licence
// into `folder`/three/ from $GGX_THREE_DIR, else /usr/share/javascript/three
// (Debian's libjs-three); throws naming the package when they are missing.
void copy_three_js(const std::string& folder);

// Throws copy_three_js's error now, before a long run, when three.js is missing.
void require_three_js();

} // namespace ggxapp
