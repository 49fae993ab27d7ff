// skip.cpp - recording skipped test cases (skip.hpp).
#include "skip.hpp"

#include <cstdlib>
#include <cstring>
#include <iostream>

#include <doctest/doctest.h>

namespace ggxtest {

namespace {

std::vector<std::string>& recorded_reasons()
{
    static std::vector<std::string> reasons;
    return reasons;
}

bool everything_required()
{
    const char* value = std::getenv("GGXCL_TESTS_REQUIRE_ALL");
    return value && std::strcmp(value, "1") == 0;
}

} // namespace

bool skip_unless(bool present, const std::string& reason)
{
    if (present)
        return true;
    if (everything_required()) {
        FAIL_CHECK("missing prerequisite (GGXCL_TESTS_REQUIRE_ALL=1 makes it a failure): " << reason);
        return false;
    }
    MESSAGE("SKIPPED: " << reason);
    recorded_reasons().push_back(reason);
    return false;
}

const std::vector<std::string>& skip_reasons()
{
    return recorded_reasons();
}

int exit_status_after(int doctest_status)
{
    if (doctest_status != 0 || recorded_reasons().empty())
        return doctest_status;
    std::cout << "[ggxtest] " << recorded_reasons().size() << " test case(s) skipped, exit status "
              << skip_exit_code << ":\n";
    for (const std::string& reason : recorded_reasons())
        std::cout << "[ggxtest]   " << reason << "\n";
    return skip_exit_code;
}

} // namespace ggxtest
