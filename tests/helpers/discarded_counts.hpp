// discarded_counts.hpp - a user sampler's histogram against a built-in
// method's of the same samples: the user's discarded samples (o below the
// horizon with weight 0) are counted apart (Histogram::invalid), the
// method's in the bins below the horizon.  Same counts above the horizon,
// none below for the user, its discarded count the method's count below.
#pragma once

#include <cstdint>

#include <doctest/doctest.h>

#include <ggxcl/ggxcl.hpp>

namespace ggxtest {

inline void check_counts_with_discards(const ggxcl::Histogram& user, const ggxcl::Histogram& method)
{
    REQUIRE(user.counts.size() == method.counts.size());
    REQUIRE(method.bins_z % 2 == 0);
    const std::size_t below = std::size_t(method.bins_z / 2) * std::size_t(method.bins_phi);
    std::uint64_t method_below = 0, user_below = 0;
    for (std::size_t b = 0; b < below; ++b) {
        method_below += method.counts[b];
        user_below += user.counts[b];
    }
    CHECK(user_below == 0);
    CHECK(user.invalid == method_below);
    CHECK(method_below > 0);  // the comparison sees discarded samples
    for (std::size_t b = below; b < user.counts.size(); ++b)
        CHECK(user.counts[b] == method.counts[b]);
    CHECK(user.non_finite == method.non_finite);
}

} // namespace ggxtest
