# readme_methods.cmake - the README's table of methods is what `ggx methods`
# prints from the one table of methods (ggx_contract.h): fails, showing both,
# when they differ.  cmake -DGGX=<ggx> -DREADME=<README.md> -P readme_methods.cmake
execute_process(COMMAND ${GGX} methods OUTPUT_VARIABLE table RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ggx methods failed: ${status}")
endif()
file(READ ${README} readme)
string(FIND "${readme}" "<!-- ggx methods -->\n${table}<!-- /ggx methods -->" found)
if(found EQUAL -1)
  message(FATAL_ERROR "README.md's table of methods (between <!-- ggx methods --> and <!-- /ggx methods -->) "
                      "is not what `ggx methods` prints; paste this there:\n${table}")
endif()
