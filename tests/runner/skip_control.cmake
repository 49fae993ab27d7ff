# skip_control.cmake - the negative control of skip.hpp: runs skip_probe
# (PROBE) with its piece hidden and shown, with and without
# GGXCL_TESTS_REQUIRE_ALL, and checks the exit status and output of each:
# a missing piece is a skip (77, the reason printed) without the variable
# and a failure with it; a failure beside a skip is still a failure; with the
# piece present the suite passes.
# Usage: cmake -DPROBE=path/to/skip_probe -P skip_control.cmake

# Runs PROBE with the NAME=VALUE words after `text` in its environment (the
# variables above unset unless given) and fails unless it exits `status` and
# prints `text`.
function(expect name status text)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=GGXCL_TESTS_REQUIRE_ALL --unset=GGX_SKIP_PROBE_HIDE
                          --unset=GGX_SKIP_PROBE_FAIL ${ARGN} ${PROBE}
                  RESULT_VARIABLE got OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT got STREQUAL status)
    message(FATAL_ERROR "${name}: exit status ${got}, expected ${status}\n${out}${err}")
  endif()
  string(FIND "${out}${err}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${name}: the output does not say '${text}'\n${out}${err}")
  endif()
  message(STATUS "${name}: exit status ${got}, as expected")
endfunction()

set(reason "needs the probe's piece (GGX_SKIP_PROBE_HIDE=1)")
expect("piece present" 0 "Status: SUCCESS")
expect("piece missing" 77 "SKIPPED: ${reason}" GGX_SKIP_PROBE_HIDE=1)
expect("piece missing, summary" 77 "[ggxtest] 1 test case(s) skipped, exit status 77" GGX_SKIP_PROBE_HIDE=1)
expect("piece missing under GGXCL_TESTS_REQUIRE_ALL=1" 1 "${reason}" GGX_SKIP_PROBE_HIDE=1 GGXCL_TESTS_REQUIRE_ALL=1)
expect("piece missing under GGXCL_TESTS_REQUIRE_ALL=0" 77 "SKIPPED: ${reason}" GGX_SKIP_PROBE_HIDE=1
       GGXCL_TESTS_REQUIRE_ALL=0)
expect("a failure beside a skip" 1 "SKIPPED: ${reason}" GGX_SKIP_PROBE_HIDE=1 GGX_SKIP_PROBE_FAIL=1)
