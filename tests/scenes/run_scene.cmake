# Run a bundled scene exactly as shipped and check its results.csv.
# The scene runs in WORK_DIR (in the build tree), so its relative
# Output/Directory lands there and nothing is written to the source tree.
# With APPEND (a .prm file) the scene runs with those entries appended
# (later entries win): WORK_DIR/scene.prm.
# Usage: cmake -DEXE=... -DPRM=... -DRESULTS=<path relative to WORK_DIR>
#              -DCHECKS=... -DCHECKER=... -DWORK_DIR=... [-DAPPEND=...]
#              -P run_scene.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
if(APPEND)
  file(READ ${PRM} scene)
  file(READ ${APPEND} entries)
  file(WRITE ${WORK_DIR}/scene.prm "${scene}\n${entries}")
  set(PRM ${WORK_DIR}/scene.prm)
endif()
execute_process(COMMAND ${EXE} ${PRM}
                RESULT_VARIABLE exit_code
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err
                WORKING_DIRECTORY ${WORK_DIR})
message("${out}${err}")
if(NOT exit_code EQUAL 0)
  message(FATAL_ERROR "the scene exited with code ${exit_code}")
endif()
execute_process(COMMAND ${CHECKER} ${CHECKS} ${WORK_DIR}/${RESULTS}
                RESULT_VARIABLE check_code
                OUTPUT_VARIABLE check_out
                ERROR_VARIABLE check_err)
message("${check_out}${check_err}")
if(NOT check_code EQUAL 0)
  message(FATAL_ERROR "a number of the scene is off its reference")
endif()
