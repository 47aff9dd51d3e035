# A run that fails leaves no results.csv behind, also not an earlier run's:
# a good run writes its results into a folder, then a failing run into the
# same folder must remove them (and its own partial output).
# Usage: cmake -DEXE=... -DSOURCE_DIR=... -DWORK_DIR=... -P stale_results_removed.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
# The scene of tests/prm/bad_failure_after_vtu.prm: with a rough interface
# it runs; as shipped (smooth, under H) nothing resists the foundation.
file(READ ${SOURCE_DIR}/tests/prm/bad_failure_after_vtu.prm scene)
file(WRITE ${WORK_DIR}/good.prm "${scene}
subsection Interfaces
  set Interfaces = 5: rough
end
subsection Output
  set Directory = out
end
")
file(WRITE ${WORK_DIR}/bad.prm "${scene}
subsection Output
  set Directory = out
end
")
execute_process(COMMAND ${EXE} good.prm RESULT_VARIABLE exit_code
                OUTPUT_QUIET ERROR_QUIET WORKING_DIRECTORY ${WORK_DIR})
if(NOT exit_code EQUAL 0 OR NOT EXISTS ${WORK_DIR}/out/results.csv)
  message(FATAL_ERROR "the good run must succeed and write results.csv")
endif()
execute_process(COMMAND ${EXE} bad.prm RESULT_VARIABLE exit_code
                OUTPUT_VARIABLE out ERROR_VARIABLE err
                WORKING_DIRECTORY ${WORK_DIR})
message(STATUS "exit code ${exit_code}: ${err}")
if(exit_code EQUAL 0)
  message(FATAL_ERROR "the bad run must fail")
endif()
file(GLOB leftovers ${WORK_DIR}/out/*)
if(leftovers)
  message(FATAL_ERROR "an earlier run's results are left: ${leftovers}")
endif()
message(STATUS "2 passed, 0 failed")
