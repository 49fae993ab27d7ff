// histogram_verdicts.hpp - the checks `ggx histogram --sampler` wrote to
// PREFIX.json, by name: whether each passed and its one-line summary; and
// the negative controls of tests/user_samplers with the checks each must
// fail and pass and what they must say, and the exact samplers that must
// pass every check.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
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

// The measured numbers of one check in PREFIX.json (null when there is no such check).
inline nlohmann::json histogram_numbers(const std::filesystem::path& prefix, const std::string& name)
{
    std::ifstream in(prefix.string() + ".json");
    const nlohmann::json doc = nlohmann::json::parse(in);  // kept: the loop below reads into it
    for (const nlohmann::json& check : doc["checks"])
        if (check["name"] == name)
            return check["numbers"];
    return nullptr;
}

// Every check a user sampler gets (histogram_job.cpp's order; "the claimed ..." only for a claim).
inline std::vector<std::string> all_user_checks(const std::string& claim)
{
    std::vector<std::string> names = {"its own pdf", "its own pdf, in theta", "pdf integrates to 1", "pdf where it samples",
                                      "mean weight is the albedo", "pdf from (i, o)"};
    if (!claim.empty()) {
        names.push_back("the claimed " + claim);
        names.push_back("pdf of the claimed " + claim);
    }
    return names;
}

struct HistogramControl {
    const char* file;  // in tests/user_samplers
    const char* args;  // the configuration
    std::vector<std::string> failing, passing;
    // (check, words its summary must hold): what it says of the fault, by how much and which way.
    std::vector<std::pair<std::string, std::string>> says = {};
};

// The negative controls of tests/user_samplers, at the configuration where each fault shows.
inline std::vector<HistogramControl> histogram_controls()
{
    return {
        {"swapped_axes.h", "--alpha 0.2,0.6", {"its own pdf", "the claimed vndf"}, {"pdf integrates to 1"}},
        {"pdf_doubled.h",
         "--alpha 0.2,0.6",
         {"pdf from (i, o)", "pdf integrates to 1"},
         {"the claimed vndf", "pdf of the claimed vndf"},
         {{"pdf from (i, o)", "another normalization: a factor 0.5000 (= 1/2)"}}},
    };
}

// The controls of tests/user_samplers/harness: engine-style faults the harness must name (OpenCL C only).
inline std::vector<HistogramControl> harness_controls()
{
    return {
        {"harness/pdf_zero_kept.h",
         "--alpha 0.8 --theta 80",
         {"pdf from (i, o)", "pdf of the claimed vndf", "mean weight is the albedo"},
         {},
         {{"pdf from (i, o)", "kept samples (o above the horizon, or a weight) have pdf <= 0"}}},
        {"harness/pdf_not_a_density.h",  // NaN at alpha 0.4
         "--alpha 0.4 --theta 60",
         {"its own pdf", "its own pdf, in theta", "pdf integrates to 1", "pdf where it samples", "pdf from (i, o)"},
         {"the claimed vndf"},
         {{"its own pdf", "expected counts not finite"},
          {"pdf integrates to 1", "not finite"},
          {"pdf from (i, o)", "have a pdf that is NaN or infinite"}}},
        {"harness/pdf_not_a_density.h",  // +infinity at alpha 0.5
         "--alpha 0.5 --theta 60",
         {"its own pdf", "its own pdf, in theta", "pdf integrates to 1", "pdf where it samples", "pdf from (i, o)"},
         {"the claimed vndf"},
         {{"its own pdf", "expected counts not finite"}, {"pdf integrates to 1", "not finite"}}},
        {"harness/pdf_not_a_density.h",  // 0 at alpha 0.6
         "--alpha 0.6 --theta 60",
         {"its own pdf", "its own pdf, in theta", "pdf integrates to 1", "pdf from (i, o)"},
         {"the claimed vndf"},
         {{"its own pdf", "no degree of freedom"}, {"its own pdf", "samples landed in bins where the pdf is 0"}}},
        {"harness/ndf_alpha_epsilon.h",
         "--alpha 0.05",
         {"pdf integrates to 1"},
         {"its own pdf", "the claimed ndf", "pdf where it samples"},
         {{"pdf integrates to 1", "integrates to 1: 1.004"}}},
        {"harness/ndf_alpha_epsilon.h",
         "--alpha 0.01 --theta 30",
         {"pdf integrates to 1"},
         {"its own pdf", "the claimed ndf"},
         {{"pdf integrates to 1", "integrates to 1: 1.09"}}},
        {"harness/bounded_ssr_weight.h",
         "--alpha 0.5 --theta 70",
         {"mean weight is the albedo"},
         {"its own pdf", "its own pdf, in theta", "pdf integrates to 1", "pdf where it samples", "pdf from (i, o)"},
         {{"mean weight is the albedo", "their mean is 1.10"}}},
        {"harness/pdf_beyond_reach.h",
         "--alpha 0.5 --theta 70",
         {"pdf integrates to 1", "pdf where it samples"},
         {"its own pdf", "mean weight is the albedo", "pdf from (i, o)"},
         {{"pdf where it samples", "positive where the sampler never goes"}}},
        {"harness/vndf_pdf_over_vh.h",
         "--alpha 0.5 --theta 70",
         {"its own pdf", "pdf of the claimed vndf", "mean weight is the albedo"},
         {"the claimed vndf", "pdf from (i, o)"},
         {{"pdf of the claimed vndf", "the shape differs"}}},
        {"harness/iso_g1_pdf.h",
         "--alpha 0.5,0.1 --theta 60 --phi 30",
         {"pdf integrates to 1", "pdf of the claimed vndf"},
         {"its own pdf", "the claimed vndf", "pdf from (i, o)"},
         {{"pdf of the claimed vndf", "another normalization: a factor 1.059"}}},
        {"harness/wider_lobe.h",
         "--alpha 0.05 --theta 0",
         {"its own pdf, in theta"},
         {"pdf integrates to 1", "pdf from (i, o)"},
         {{"its own pdf, in theta", "64 rings of equal mass in theta"}}},
        {"harness/mirrored_basis.h",
         "--alpha 0.5 --theta 70",
         {"its own pdf", "the claimed vndf", "mean weight is the albedo"},
         {"pdf from (i, o)"}},
    };
}

// The library's methods, and engine conventions that are right, as user samplers: every check
// passes, at the configurations where the harness once gave false failures.  The first three
// (each kind of claim, the three false failures) run on both APIs; the rest on OpenCL.
inline std::vector<HistogramControl> harness_exact(bool both_apis_only = false)
{
    std::vector<HistogramControl> rows = {
        {"harness/heitz_copy.h", "--alpha 0.05,0.4 --theta 80 --phi 120", {}, all_user_checks("vndf")},
        {"harness/ndf_copy.h", "--alpha 0.5,0.1 --theta 60 --phi 30", {}, all_user_checks("ndf")},
        {"harness/bounded_discards.h", "--alpha 0.8 --theta 85", {}, all_user_checks("")},
        {"caps_copy.h", "--alpha 0.05,0.4 --theta 80 --phi 120", {}, all_user_checks("vndf")},
        {"harness/ndf_copy.h", "--alpha 0.01 --theta 30", {}, all_user_checks("ndf")},
        {"harness/bounded_own.h", "--alpha 0.8 --theta 85", {}, all_user_checks("")},
        {"harness/bounded_discards_m.h", "--alpha 0.5 --theta 70", {}, all_user_checks("")},
        {"harness/m_not_unit.h", "--alpha 0.3 --theta 45 --of m", {}, all_user_checks("vndf")},
    };
    if (both_apis_only)
        rows.resize(3);
    return rows;
}

} // namespace ggxtest
