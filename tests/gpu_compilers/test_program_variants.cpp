// test_program_variants.cpp - the enumeration of the runtime's programs that
// the GPU compilers build (program_variants.hpp): every option value and
// every reachable pair of values appears, every variant is one a request
// can make, and a request's options come from its variant.
#include <doctest/doctest.h>

#include <set>
#include <tuple>

#include "program_variants.hpp"

using namespace ggxcl;
using namespace ggxcl::detail;

namespace {

// Every (option a, value, option b, value) pair in `variants` of one kind.
std::set<std::tuple<int, int, int, int>> pairs_in(const std::vector<ProgramVariant>& variants, ProgramKind kind,
                                                  const std::vector<ProgramOption>& options)
{
    std::set<std::tuple<int, int, int, int>> out;
    for (const ProgramVariant& v : variants)
        if (v.kind == kind)
            for (int a = 0; a < int(options.size()); ++a)
                for (int b = a + 1; b < int(options.size()); ++b)
                    out.insert({a, options[std::size_t(a)].get(v), b, options[std::size_t(b)].get(v)});
    return out;
}

SampleParams caps_request()
{
    SampleParams p;
    p.method = Method::caps;
    p.alpha_x = p.alpha_y = 0.3f;
    p.view = view_from_angles(60.0, 0.0);
    return p;
}

} // namespace

TEST_CASE("the covering set holds only reachable variants, each once")
{
    std::set<std::string> keys;
    for (const ProgramVariant& v : covering_variants()) {
        CHECK(variant_is_reachable(v));
        CHECK(keys.insert(variant_key(v)).second);
    }
}

TEST_CASE("every value of every option appears in the bulk programs")
{
    const std::vector<ProgramOption> options = program_options();
    const std::vector<ProgramVariant> variants = covering_variants();
    for (const ProgramOption& o : options) {
        if (o.name.rfind("histogram.", 0) == 0)
            continue;  // bins belong to the histogram programs, checked below
        std::set<int> seen;
        for (const ProgramVariant& v : variants)
            if (v.kind == ProgramKind::bulk)
                seen.insert(o.get(v));
        INFO(o.name);
        CHECK(int(seen.size()) == o.value_count);
    }
    std::set<int> bins, of_m;
    for (const ProgramVariant& v : variants)
        if (v.kind == ProgramKind::histogram)
            bins.insert(options[options.size() - 2].get(v)), of_m.insert(options.back().get(v));
    CHECK(bins.size() == 2);
    CHECK(of_m.size() == 2);
}

TEST_CASE("every pair of values that a reachable bulk variant can hold appears")
{
    const std::vector<ProgramOption> options = program_options();
    const auto covered = pairs_in(covering_variants(), ProgramKind::bulk, options);
    // Spot checks across the list, fields and flags; and a pair no variant can hold is absent.
    auto index = [&](const std::string& name) {
        for (std::size_t k = 0; k < options.size(); ++k)
            if (options[k].name == name)
                return int(k);
        FAIL("no option " << name);
        return -1;
    };
    const int method = index("method"), world = index("GGX_WORLD_SPACE"), iso = index("GGX_ISOTROPIC");
    for (int m = 0; m < int(all_methods.size()); ++m)
        for (int w = 0; w < 2; ++w)
            CHECK(covered.count({method, m, world, w}) == 1);
    CHECK(covered.count({index("precision"), 1, index("write_mask.u"), 1}) == 1);
    CHECK(covered.count({index("GGX_PER_SAMPLE_NORMAL"), 0, index("GGX_NORMAL_IS_Z"), 1}) == 1);
    CHECK(covered.count({index("GGX_PER_SAMPLE_NORMAL"), 1, index("GGX_NORMAL_IS_Z"), 1}) == 0);
    CHECK(covered.count({iso, 0, world, 1}) == 0);
    CHECK(covered.count({method, int(Method::bounded), index("GGX_DIELECTRIC"), 1}) == 0);
    CHECK(covered.count({method, int(Method::caps), index("GGX_IMPORTANCE"), 1}) == 1);
    // The number of pairs: all value pairs less those that break a rule of variant_is_reachable.
    std::size_t all = 0;
    for (std::size_t a = 0; a < options.size(); ++a)
        for (std::size_t b = a + 1; b < options.size(); ++b)
            if (options[a].name.rfind("histogram.", 0) != 0 && options[b].name.rfind("histogram.", 0) != 0)
                all += std::size_t(options[a].value_count * options[b].value_count);
    const std::size_t excluded = 1 /* iso 0, world 1 */ + 1 /* caps-iso, iso 0 */ + 1 /* normal 1, is_z 1 */ +
                                 1 /* dielectric 0, importance 1 */ + 1 /* bounded, dielectric 1 */ +
                                 1 /* bounded, importance 1 (needs a dielectric) */;
    std::size_t bulk_pairs = 0;
    for (const auto& p : covered)
        bulk_pairs += options[std::size_t(std::get<0>(p))].name.rfind("histogram.", 0) != 0 &&
                      options[std::size_t(std::get<2>(p))].name.rfind("histogram.", 0) != 0;
    CHECK(bulk_pairs == all - excluded);
}

TEST_CASE("a request's variant is reachable and gives its options")
{
    SampleParams p = caps_request();
    ProgramVariant v = variant_of(ProgramKind::bulk, p, 5);
    CHECK(variant_is_reachable(v));
    CHECK(v.isotropic);
    CHECK_FALSE(v.below_horizon);
    CHECK(v.normal_is_z);
    CHECK(variant_defines(v) ==
          "-DGGX_METHOD=3 -DGGX_WRITE_MASK=5 -DGGX_SEQUENCE=0 -DGGX_PER_SAMPLE_VIEW=0 -DGGX_PER_SAMPLE_ALPHA=0 "
          "-DGGX_PER_SAMPLE_NORMAL=0 -DGGX_PER_SAMPLE_UNIFORMS=0 -DGGX_ISOTROPIC=1 -DGGX_BELOW_HORIZON=0 "
          "-DGGX_WORLD_SPACE=0 -DGGX_GUARDS=1 -DGGX_NORMAL_IS_Z=1 -DGGX_DIELECTRIC=0 -DGGX_IMPORTANCE=0 -DGGX_EVAL=0");
    p.alpha_y = 0.5f;
    p.view = {0.5f, 0.0f, -0.8f};
    p.guards = false;
    v = variant_of(ProgramKind::bulk, p, 5);
    CHECK_FALSE(v.isotropic);
    CHECK(v.below_horizon);
    CHECK_FALSE(v.guards);
    CHECK(variant_is_reachable(v));
}

TEST_CASE("what no request makes is unreachable")
{
    ProgramVariant v = variant_of(ProgramKind::bulk, caps_request(), 5);
    v.method = Method::caps_iso;
    v.isotropic = false;
    CHECK_FALSE(variant_is_reachable(v));
    SampleParams unguarded = caps_request();
    unguarded.guards = false;
    v = variant_of(ProgramKind::furnace, unguarded, 1u << 4);
    CHECK(variant_is_reachable(v));
    v.write_mask = 5;  // a furnace writes the weight only
    CHECK_FALSE(variant_is_reachable(v));
    v = variant_of(ProgramKind::histogram, caps_request(), 0);
    CHECK_FALSE(variant_is_reachable(v));  // no bins yet
    v.bins = {32, 64, false};
    CHECK(variant_is_reachable(v));
    CHECK(variant_defines(v).find("-DGGX_BINS_Z=32 -DGGX_BINS_PHI=64 -DGGX_BIN_M=0") != std::string::npos);
}
