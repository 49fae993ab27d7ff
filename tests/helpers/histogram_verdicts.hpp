// histogram_verdicts.hpp - the checks `ggx histogram --sampler` wrote to
// PREFIX.json, by name: whether each passed and its one-line summary; and
// the negative controls of tests/user_samplers with the checks each must
// fail and pass.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ggxtest {

struct HistogramVerdict {
    bool passed = false;
    std::string summary;
};

inline std::map<std::string, HistogramVerdict> histogram_verdicts(const std::filesystem::path& prefix)
{
    std::ifstream in(prefix.string() + ".json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    std::map<std::string, HistogramVerdict> out;
    for (const nlohmann::json& check : doc["checks"])
        out[check["name"].get<std::string>()] = {check["passed"].get<bool>(), check["summary"].get<std::string>()};
    return out;
}

struct HistogramControl {
    const char* file;  // in tests/user_samplers
    std::vector<std::string> failing, passing;
};

inline std::vector<HistogramControl> histogram_controls()
{
    return {
        {"swapped_axes.h", {"its own pdf", "the claimed vndf"}, {"pdf integrates to 1"}},
        {"pdf_doubled.h", {"pdf from (i, o)", "pdf integrates to 1"}, {"the claimed vndf", "pdf of the claimed vndf"}},
    };
}

} // namespace ggxtest
