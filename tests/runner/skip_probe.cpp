// skip_probe.cpp - a suite for the negative control of the skip mechanism
// (skip_control.cmake): one case needs a piece that the environment hides
// (GGX_SKIP_PROBE_HIDE=1), one needs nothing and fails on request
// (GGX_SKIP_PROBE_FAIL=1), so that each exit status of the runner can be
// brought about: 0, 77 (skipped), 1 (failed; also with a skip beside it).
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "skip.hpp"

namespace {

bool set_to_one(const char* variable)
{
    const char* value = std::getenv(variable);
    return value && std::string(value) == "1";
}

} // namespace

TEST_CASE("a case that needs the probe's piece")
{
    if (!ggxtest::skip_unless(!set_to_one("GGX_SKIP_PROBE_HIDE"), "needs the probe's piece (GGX_SKIP_PROBE_HIDE=1)"))
        return;
    CHECK(true);
}

TEST_CASE("a case that needs nothing")
{
    CHECK_FALSE(set_to_one("GGX_SKIP_PROBE_FAIL"));
}
