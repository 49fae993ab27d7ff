// doctest_main.cpp - the doctest runner shared by the test executables: its
// exit status is doctest's, or skip_exit_code (77) when a case was skipped
// for a missing prerequisite and none failed (skip.hpp).
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "skip.hpp"

int main(int argc, char** argv)
{
    doctest::Context context(argc, argv);
    const int status = context.run();
    if (context.shouldExit())  // --help, --list-test-cases, ...
        return status;
    return ggxtest::exit_status_after(status);
}
