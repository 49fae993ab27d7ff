// cli_reports.hpp - what the user-sampler CLI tests read back of `ggx
// stress` and `ggx converge`: each sampler's stress rows (by "METHOD SIDE",
// the cells after the method and side up to the accuracy columns, which a
// user sampler, with no reference, leaves at 0) and NaN/Inf totals, and each
// sampler's convergence curve (the CSV's rows by method, before the speeds).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace ggxtest {

struct StressRows {
    std::map<std::string, std::vector<std::string>> rows;
    std::map<std::string, std::uint64_t> nan_inf;
};

inline StressRows stress_rows(const std::string& csv)
{
    StressRows out;
    std::istringstream lines(csv);
    std::string line;
    std::getline(lines, line);
    while (std::getline(lines, line)) {
        const std::string key = csv_cell(csv, line, "method") + " " + csv_cell(csv, line, "side");
        const std::size_t after_side = line.find(',', line.find(',') + 1);
        const std::size_t accuracy = line.rfind(',', line.rfind(',') - 1);  // inaccurate, inaccurate_edge
        out.rows[key].push_back(line.substr(after_side, accuracy - after_side));
        out.nan_inf[key] += std::stoull(csv_cell(csv, line, "nan_inf"));
    }
    return out;
}

inline std::map<std::string, std::vector<std::string>> converge_curves(const std::filesystem::path& csv_path)
{
    std::map<std::string, std::vector<std::string>> curves;
    std::istringstream lines(read_all(csv_path));
    std::string line;
    std::getline(lines, line);
    while (std::getline(lines, line) && !line.empty() && line.find("ns_per_sample") == std::string::npos)
        curves[line.substr(0, line.find(','))].push_back(line.substr(line.find(',')));
    return curves;
}

} // namespace ggxtest
