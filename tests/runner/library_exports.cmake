# library_exports.cmake - libggxcl exports no test machinery: `nm -D` of the
# shared library lists none of the names below (the pairwise covering of the
# program variants lives in tests/support, the fault injection is reached
# through GGXCL_INJECT_FAULT only).  Control: the same search finds
# covering_variants in the test support library that now holds it.
#   cmake -DLIBRARY=<libggxcl.so> -DSUPPORT=<libggx_program_variants.a> -P library_exports.cmake
set(test_only covering_variants injected_fault params_validations)
function(symbols_of file options out)
  execute_process(COMMAND nm ${options} -C ${file} OUTPUT_VARIABLE table RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "nm ${options} ${file} failed (${status}); nm is in binutils")
  endif()
  set(${out} "${table}" PARENT_SCOPE)
endfunction()
symbols_of(${LIBRARY} "-D;--defined-only" exported)
foreach(name ${test_only})
  string(FIND "${exported}" "${name}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${LIBRARY} exports the test-only ${name}")
  endif()
endforeach()
symbols_of(${SUPPORT} "--defined-only" support)
string(FIND "${support}" "covering_variants" at)
if(at EQUAL -1)
  message(FATAL_ERROR "control: covering_variants not found in ${SUPPORT}: the search finds nothing")
endif()
message(STATUS "libggxcl exports none of: ${test_only}")
