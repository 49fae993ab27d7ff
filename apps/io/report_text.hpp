// report_text.hpp - what the Markdown reports of `ggx bench` and
// `ggx converge` share: the date line and the links from a report to the
// charts written beside it.
#pragma once

#include <string>

namespace ggxapp {

std::string utc_now();  // "2026-12-02 05:30 UTC"

// `path` as a link from the Markdown file `markdown` (relative to its
// folder); `path` itself when there is no Markdown file.
std::string relative_to(const std::string& path, const std::string& markdown);

} // namespace ggxapp
