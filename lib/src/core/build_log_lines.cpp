// build_log_lines.cpp - a program's physical lines read from its `#line`
// markers, and a build log's locations rewritten through them.
#include "build_log_lines.hpp"

#include <cctype>
#include <regex>

namespace ggxcl::detail {

namespace {

// Whether `text` is a `#line N` or `#line N "file"` directive; `file` is empty when it names none.
bool read_line_directive(const std::string& text, int& number, std::string& file)
{
    static const std::regex directive(R"re(^\s*#\s*line\s+(\d{1,9})(?:\s+"([^"]*)")?\s*$)re");
    std::smatch match;
    if (!std::regex_match(text, match, directive))
        return false;
    number = std::stoi(match[1]);
    file = match[2];
    return true;
}

bool is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

bool is_digit(char c)
{
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// A location `NAME:L:` in the log: the colon after NAME, L, and the end of `NAME:L:`.
struct Location {
    std::size_t colon = 0, end = 0;
    long line = 0;
};

// The first `NAME:L:` of the whitespace-free token at `start` (NAME not empty).
bool find_location(const std::string& log, std::size_t start, Location& found)
{
    for (std::size_t colon = start + 1; colon < log.size() && !is_space(log[colon]); ++colon) {
        if (log[colon] != ':')
            continue;
        std::size_t end = colon + 1;
        while (end < log.size() && is_digit(log[end]))
            ++end;
        const std::size_t digits = end - colon - 1;
        if (digits == 0 || digits > 9 || end == log.size() || log[end] != ':')
            continue;
        found = {colon, end + 1, std::stol(log.substr(colon + 1, digits))};
        return true;
    }
    return false;
}

// Whether the text before `colon` ends with a marker's file name that covers the token at `start`
// (a name with spaces starts before the token).
bool names_marker_file(const std::string& log, std::size_t start, std::size_t colon, const ProgramLines& lines)
{
    for (const std::string& file : lines.files)
        if (file.size() >= colon - start && file.size() <= colon &&
            log.compare(colon - file.size(), file.size(), file) == 0)
            return true;
    return false;
}

// Where physical line `line` comes from; null for a line out of range or without a file.
const SourceLine* origin_of(const ProgramLines& lines, long line)
{
    if (line < 1 || line > static_cast<long>(lines.lines.size()))
        return nullptr;
    const SourceLine& origin = lines.lines[line - 1];
    return origin.file.empty() ? nullptr : &origin;
}

// The origin of the location that starts at `start`, or null when there is none to map.
const SourceLine* mapped_origin(const std::string& log, std::size_t start, const ProgramLines& lines, Location& at)
{
    const bool token_start = (start == 0 || is_space(log[start - 1])) && !is_space(log[start]);
    if (!token_start || !find_location(log, start, at) || names_marker_file(log, start, at.colon, lines))
        return nullptr;
    return origin_of(lines, at.line);
}

} // namespace

ProgramLines program_lines(const std::string& source)
{
    ProgramLines table;
    SourceLine next;  // where the next line that is not a directive comes from
    for (std::size_t start = 0;;) {
        const std::size_t end = source.find('\n', start);
        int number = 0;
        std::string file;
        if (read_line_directive(source.substr(start, end - start), number, file)) {
            if (!file.empty()) {
                next.file = file;
                table.files.insert(file);
            }
            next.line = number;
            table.lines.push_back(SourceLine{});
        } else {
            table.lines.push_back(next);
            ++next.line;
        }
        if (end == std::string::npos)
            return table;
        start = end + 1;
    }
}

std::string map_build_log(const std::string& log, const ProgramLines& lines)
{
    std::string mapped;
    mapped.reserve(log.size());
    for (std::size_t k = 0; k < log.size();) {
        Location at;
        if (const SourceLine* origin = mapped_origin(log, k, lines, at)) {
            mapped += origin->file + ":" + std::to_string(origin->line) + ":";
            k = at.end;
        } else {
            mapped += log[k++];
        }
    }
    return mapped;
}

} // namespace ggxcl::detail
