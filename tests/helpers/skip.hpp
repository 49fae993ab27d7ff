// skip.hpp - test cases whose prerequisite (a program, a package, a second
// OpenCL implementation) is missing on this machine.  skip_unless prints why
// and records the skip; the case then returns, the suite's other cases run,
// and the runner (doctest_main.cpp) exits with skip_exit_code when nothing
// failed, which CTest reports as "Skipped" (SKIP_RETURN_CODE).  With
// GGXCL_TESTS_REQUIRE_ALL=1 (CI, where everything is installed) a missing
// prerequisite fails the case instead.
#pragma once

#include <string>
#include <vector>

namespace ggxtest {

// The runner's exit status when some case was skipped and none failed.
constexpr int skip_exit_code = 77;

// Whether the case may go on: `present`, else false after recording a skip
// (or, under GGXCL_TESTS_REQUIRE_ALL=1, a failure) with `reason`, which names
// the missing piece and how to install it.
//   if (!ggxtest::skip_unless(found, "needs three.js (apt-get install libjs-three)"))
//       return;
bool skip_unless(bool present, const std::string& reason);

// The reasons of the skips recorded in this run, in order.
const std::vector<std::string>& skip_reasons();

// The runner's exit status from doctest's: doctest's when it failed or no
// case was skipped, skip_exit_code otherwise.
int exit_status_after(int doctest_status);

} // namespace ggxtest
