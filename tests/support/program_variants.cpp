// program_variants.cpp - the options of the runtime's programs, and a pairwise
// covering set of their reachable variants.
#include "program_variants.hpp"

#include <map>
#include <random>
#include <set>
#include <tuple>

#include "device_contract.hpp"

namespace ggxcl::detail {

namespace {

// The histogram bins an enumeration tries: `ggx histogram`'s default and the smallest.
constexpr HistogramBins bin_choices[] = {{32, 64, false}, {1, 1, false}};

void add_list_options(std::vector<ProgramOption>& out)
{
    out.push_back({"method", int(all_methods.size()), [](const ProgramVariant& v) { return method_id(v.method); },
                   [](ProgramVariant& v, int k) { v.method = all_methods[std::size_t(k)]; }});
    out.push_back({"precision", int(all_precisions.size()),
                   [](const ProgramVariant& v) { return static_cast<int>(v.precision); },
                   [](ProgramVariant& v, int k) { v.precision = all_precisions[std::size_t(k)]; }});
    out.push_back({"sequence", int(all_sequences.size()), [](const ProgramVariant& v) { return sequence_id(v.sequence); },
                   [](ProgramVariant& v, int k) { v.sequence = all_sequences[std::size_t(k)]; }});
}

void add_mask_options(std::vector<ProgramOption>& out)
{
    for (Field f : all_fields) {
        const unsigned bit = 1u << static_cast<int>(f);
        out.push_back({"write_mask." + std::string(field_name(f)), 2,
                       [bit](const ProgramVariant& v) { return (v.write_mask & bit) ? 1 : 0; },
                       [bit](ProgramVariant& v, int k) { v.write_mask = k ? v.write_mask | bit : v.write_mask & ~bit; }});
    }
}

void add_flag_options(std::vector<ProgramOption>& out)
{
#define GGX_PROGRAM_FLAG_OPTION(field, macro)                                                              \
    out.push_back({macro, 2, [](const ProgramVariant& v) { return v.field ? 1 : 0; },                     \
                   [](ProgramVariant& v, int k) { v.field = k != 0; }});
    GGX_PROGRAM_FLAGS(GGX_PROGRAM_FLAG_OPTION)
#undef GGX_PROGRAM_FLAG_OPTION
}

void add_histogram_options(std::vector<ProgramOption>& out)
{
    out.push_back({"histogram.bins", int(std::size(bin_choices)),
                   [](const ProgramVariant& v) {
                       for (std::size_t k = 0; k < std::size(bin_choices); ++k)
                           if (v.bins.bins_z == bin_choices[k].bins_z && v.bins.bins_phi == bin_choices[k].bins_phi)
                               return int(k);
                       return -1;
                   },
                   [](ProgramVariant& v, int k) {
                       v.bins.bins_z = bin_choices[k].bins_z;
                       v.bins.bins_phi = bin_choices[k].bins_phi;
                   }});
    out.push_back({"histogram.of_m", 2, [](const ProgramVariant& v) { return v.bins.of_m ? 1 : 0; },
                   [](ProgramVariant& v, int k) { v.bins.of_m = k != 0; }});
}

// A value of two options: (option a, value of a, option b, value of b), a < b.
using ValuePair = std::tuple<int, int, int, int>;

// Greedy pairwise covering of one program kind.
class CoveringBuilder {
public:
    CoveringBuilder(ProgramKind kind, const std::vector<ProgramOption>& options)
        : kind_(kind), options_(options), random_(20231)
    {
    }

    std::vector<ProgramVariant> build()
    {
        find_feasible_pairs();
        std::vector<ProgramVariant> chosen;
        while (!uncovered_.empty()) {
            ProgramVariant best = candidate_with(*uncovered_.begin());
            std::size_t best_gain = gain(best);
            for (int tries = 0; tries < 48; ++tries) {
                auto pick = std::next(uncovered_.begin(), std::ptrdiff_t(random_() % uncovered_.size()));
                ProgramVariant c = candidate_with(*pick);
                if (std::size_t g = gain(c); g > best_gain)
                    best = c, best_gain = g;
            }
            cover(best);
            chosen.push_back(best);
        }
        return chosen;
    }

private:
    ProgramVariant random_variant()
    {
        ProgramVariant v;
        v.kind = kind_;
        for (const ProgramOption& o : options_)
            o.set(v, int(random_() % unsigned(o.value_count)));
        return v;
    }

    bool has(const ProgramVariant& v, const ValuePair& p) const
    {
        return options_[std::size_t(std::get<0>(p))].get(v) == std::get<1>(p) &&
               options_[std::size_t(std::get<2>(p))].get(v) == std::get<3>(p);
    }

    // A reachable variant holding pair p, or one without it where none was found.
    ProgramVariant candidate_with(const ValuePair& p)
    {
        for (int tries = 0; tries < 64; ++tries) {
            ProgramVariant v = random_variant();
            options_[std::size_t(std::get<0>(p))].set(v, std::get<1>(p));
            options_[std::size_t(std::get<2>(p))].set(v, std::get<3>(p));
            v = with_kind_fixed(v);
            if (has(v, p) && variant_is_reachable(v))
                return v;
        }
        ProgramVariant v;
        do
            v = with_kind_fixed(random_variant());
        while (!variant_is_reachable(v));
        return v;
    }

    void find_feasible_pairs()
    {
        for (int a = 0; a < int(options_.size()); ++a)
            for (int b = a + 1; b < int(options_.size()); ++b)
                for (int x = 0; x < options_[std::size_t(a)].value_count; ++x)
                    for (int y = 0; y < options_[std::size_t(b)].value_count; ++y)
                        if (ValuePair p{a, x, b, y}; has(candidate_with(p), p))
                            uncovered_.insert(p);
    }

    std::size_t gain(const ProgramVariant& v) const
    {
        std::size_t n = 0;
        for (const ValuePair& p : uncovered_)
            n += has(v, p);
        return n;
    }

    void cover(const ProgramVariant& v)
    {
        for (auto it = uncovered_.begin(); it != uncovered_.end();)
            it = has(v, *it) ? uncovered_.erase(it) : std::next(it);
    }

    ProgramKind kind_;
    const std::vector<ProgramOption>& options_;
    std::mt19937 random_;
    std::set<ValuePair> uncovered_;
};

} // namespace

std::vector<ProgramOption> program_options()
{
    std::vector<ProgramOption> out;
    add_list_options(out);
    add_mask_options(out);
    add_flag_options(out);
    add_histogram_options(out);
    return out;
}

std::vector<ProgramVariant> covering_variants()
{
    const std::vector<ProgramOption> options = program_options();
    std::vector<ProgramVariant> out;
    std::set<std::string> seen;
    for (ProgramKind kind : all_program_kinds)
        for (const ProgramVariant& v : CoveringBuilder(kind, options).build())
            if (seen.insert(variant_key(v)).second)
                out.push_back(v);
    return out;
}

} // namespace ggxcl::detail
