// completed_samples.hpp - the check of a user sampler of m alone (the
// library completes o, pdf_o, pdf_m and weight) against heitz's samples of
// the same request: m and o bit for bit, the rest within 1e-4 where heitz's
// pdf_o is positive, and enough such samples to count.
#pragma once

#include <doctest/doctest.h>

#include <ggxcl/ggxcl.hpp>

#include "bit_compare.hpp"

namespace ggxtest {

inline void check_completed_like_heitz(const ggxcl::SampleSet& mine, const ggxcl::SampleSet& heitz)
{
    CHECK(same_bits(mine.m, heitz.m));
    CHECK(same_bits(mine.o, heitz.o));
    std::size_t checked = 0;
    for (std::size_t j = 0; j < mine.count; ++j) {
        if (!(heitz.pdf_o[j] > 0.0f))
            continue;
        ++checked;
        CHECK(mine.pdf_o[j] == doctest::Approx(heitz.pdf_o[j]).epsilon(1e-4));
        CHECK(mine.pdf_m[j] == doctest::Approx(heitz.pdf_m[j]).epsilon(1e-4));
        CHECK(mine.weight[j] == doctest::Approx(heitz.weight[j]).epsilon(1e-4));
    }
    CHECK(checked > mine.count * 4 / 5);
}

} // namespace ggxtest
