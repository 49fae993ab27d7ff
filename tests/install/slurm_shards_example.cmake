# slurm_shards_example.cmake - CTest script (cmake -P) for
# examples/slurm_shards.sh: run without Slurm (every shard in turn, then
# `ggx merge`), its merged file and sidecar must equal, byte for byte, one
# `ggx sample` run over the whole range.  Inputs: GGX, SCRIPT, WORK_DIR.
# (tests/schedulers/test_slurm_cluster.sh runs it under a real Slurm.)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=SLURM_ARRAY_TASK_ID SHARDS=3 SAMPLES=60033 GGX=${GGX}
                        OUT=${WORK_DIR}/shards
                        bash ${SCRIPT}
                RESULT_VARIABLE sharded OUTPUT_VARIABLE log ERROR_VARIABLE log)
execute_process(COMMAND ${GGX} sample --method caps --alpha 0.2 --theta 70 --seed 7 --fields o,pdf_o,weight
                        -n 60033 --out ${WORK_DIR}/one.npy
                RESULT_VARIABLE whole ERROR_VARIABLE log_whole)
foreach(ext npy json)
  file(SHA256 ${WORK_DIR}/shards/caps-all.${ext} merged_${ext})
  file(SHA256 ${WORK_DIR}/one.${ext} one_${ext})
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
if(NOT sharded EQUAL 0 OR NOT whole EQUAL 0)
  message(FATAL_ERROR "slurm_shards.sh or ggx sample failed:\n${log}\n${log_whole}")
endif()
if(NOT merged_npy STREQUAL one_npy OR NOT merged_json STREQUAL one_json)
  message(FATAL_ERROR "the merged shards differ from one run over the whole range")
endif()
