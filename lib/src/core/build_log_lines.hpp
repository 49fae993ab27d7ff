// build_log_lines.hpp - a build log's locations mapped back to the files a
// program was assembled from, through the program's `#line N "file"`
// markers, for OpenCL compilers that ignore them and print the physical
// line of the whole program (`<kernel>:3918:46:`, `<source>:L:C:`,
// `input.cl:L:C:`, `/tmp/xyz.cl:L:`).
#pragma once

#include <set>
#include <string>
#include <vector>

namespace ggxcl::detail {

// Where one physical line of a program comes from: `file`'s line `line`;
// an empty `file` for a `#line` directive and for the lines before the first.
struct SourceLine {
    std::string file;
    int line = 0;
};

struct ProgramLines {
    std::vector<SourceLine> lines;  // physical line k (from 1) at k - 1
    std::set<std::string> files;    // every file name the markers give
};

// The table of `source`, read from its `#line N "file"` and `#line N`
// directives.
ProgramLines program_lines(const std::string& source);

// `log` with each location `NAME:L:C:` or `NAME:L:` (at the start of a line
// or after whitespace) whose NAME is not one of the markers' file names and
// whose physical line L has a file written as `file:line:C:` (`file:line:`);
// every other character as it was.  A log that already names the files
// (clang, PoCL) comes back unchanged.
std::string map_build_log(const std::string& log, const ProgramLines& lines);

} // namespace ggxcl::detail
