// cli_runner.hpp - what the tests of the `ggx` tool share: scratch folders
// and reading a file back whole (scratch.hpp), running the tool (GGX_BINARY,
// set by CMake or the environment: test_paths.hpp) with its exit status and
// stderr (`ggx`: kept in the test case's scratch folder), the rows of a `ggx
// bench` CSV and a cell of a CSV by its column's name.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "scratch.hpp"
#include "test_paths.hpp"

namespace ggxtest {

struct Run {
    int status;       // exit status, -1 if the tool did not exit normally
    std::string err;  // what it printed on stderr
};

// Runs `ggx ARGS` (or, with prefix_binary false, the shell command ARGS) with
// stdout discarded; stderr goes through `err_file`.
inline Run run_ggx(const std::string& args, const fs::path& err_file, bool prefix_binary = true)
{
    std::string command = (prefix_binary ? ggxtest::ggx_binary() + " " : std::string()) + args + " >/dev/null 2>" +
                          err_file.string();
    int raw = std::system(command.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_all(err_file)};
}

// Runs `ggx ARGS`, its stderr kept in the running test case's scratch folder.
inline Run ggx(const std::string& args)
{
    return run_ggx(args, ScratchFolder::current() / "stderr.txt");
}

// The first four columns of each row of a `ggx bench` CSV (after its header).
struct BenchCsvRow {
    std::string method, precision, job, line;
    double ns_median = 0;
};

inline std::vector<BenchCsvRow> bench_csv_rows(const std::string& csv_text)
{
    std::stringstream csv(csv_text);
    std::string line;
    std::getline(csv, line);  // the header
    std::vector<BenchCsvRow> rows;
    while (std::getline(csv, line)) {
        std::stringstream fields(line);
        BenchCsvRow row;
        std::string ns;
        std::getline(fields, row.method, ',');
        std::getline(fields, row.precision, ',');
        std::getline(fields, row.job, ',');
        std::getline(fields, ns, ',');
        row.ns_median = std::stod(ns);
        row.line = line;
        rows.push_back(row);
    }
    return rows;
}

// The cells of the first line of `text`, split at commas outside double
// quotes, the quotes dropped (no escaped quotes).
inline std::vector<std::string> csv_cells(const std::string& text)
{
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (char c : text.substr(0, text.find('\n'))) {
        if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            cells.emplace_back();
        else
            cells.back().push_back(c);
    }
    return cells;
}

// The cell of `line` under the column `name` of the header that starts `csv`;
// throws, naming what is wrong, when there is no such column or the line's
// cells do not match the header's.
inline std::string csv_cell(const std::string& csv, const std::string& line, const std::string& name)
{
    const std::vector<std::string> header = csv_cells(csv), cells = csv_cells(line);
    const auto at = std::find(header.begin(), header.end(), name);
    if (at == header.end())
        throw std::runtime_error("no column '" + name + "' in the CSV header: " + csv.substr(0, csv.find('\n')));
    if (cells.size() != header.size())
        throw std::runtime_error("a row of " + std::to_string(cells.size()) + " cells under a header of " +
                                 std::to_string(header.size()) + ": " + line);
    return cells[std::size_t(at - header.begin())];
}

} // namespace ggxtest
