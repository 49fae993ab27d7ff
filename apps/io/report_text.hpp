// report_text.hpp - what the reports of `ggx bench`, `converge`, `stress`
// and `demo` share: the date line, the links from a report to the charts
// written beside it, and numbers written for people (78.8 M samples/s,
// 6.12 ns, 1.2e-7) rather than as the stream prints them.
#pragma once

#include <string>

namespace ggxapp {

std::string utc_now();  // "2026-12-02 05:30 UTC"

// `path` as a link from the file `page` (relative to its folder); `path`
// itself when there is no page.
std::string relative_to(const std::string& path, const std::string& page);

// Where a command's charts go: `charts` (its --charts prefix) when given, else beside the page
// `html` (its path without the extension), else nowhere ("").
std::string charts_prefix(const std::string& charts, const std::string& html);

// `value` with `digits` digits after the point ("6.12").
std::string fixed(double value, int digits);

// `value` with `significant` digits: fixed between 1e-3 and 1e6 ("0.0123",
// "4.29", "1497"), else scientific with a short exponent ("1.2e-7"); "0" for 0.
std::string readable_number(double value, int significant = 3);

// A rate with a metric prefix: rate_text(7.87954e7, "samples/s") is "78.8 M samples/s".
std::string rate_text(double per_second, const std::string& unit);

// A duration given in nanoseconds, in the unit that reads best: "6.12 ns", "11.7 us", "92 ms", "1.5 s".
std::string duration_text(double ns);

} // namespace ggxapp
