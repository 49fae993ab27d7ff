// histogram_verdicts.hpp - the checks `ggx histogram --sampler` wrote to
// PREFIX.json, by name: whether each passed and its one-line summary.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

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

} // namespace ggxtest
