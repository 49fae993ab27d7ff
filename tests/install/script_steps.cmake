# script_steps.cmake - what the install tests' scripts share (cmake -P):
# fail() removes WORK_DIR and stops; step() runs a command, stops with its
# output when it fails, and leaves its stdout in step_output.
function(fail message)
  file(REMOVE_RECURSE ${WORK_DIR})
  message(FATAL_ERROR "${message}")
endfunction()

# Runs a command; on failure removes the work directory and stops with its output.
function(step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    fail("${name} failed (${status}):\n${out}\n${err}")
  endif()
  message(STATUS "${name}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()
