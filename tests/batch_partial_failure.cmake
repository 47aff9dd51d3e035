# A batch with one failing case still writes the rows of the cases that
# succeeded, lists the failed one on stderr, and exits non-zero; an earlier
# batch CSV is not left behind when none succeeds.
# Usage: cmake -DEXE=... -DSOURCE_DIR=... -DWORK_DIR=... -P batch_partial_failure.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
file(READ ${SOURCE_DIR}/prm/embedded-footing-graded.prm good)
file(WRITE ${WORK_DIR}/good.prm "${good}
subsection Output
  set Directory = good
  set Write vtu = false
end
")
file(WRITE ${WORK_DIR}/bad.prm "subsection Materials\n  set Materials = 0: G=-1, nu=0.3\nend\n")
execute_process(COMMAND ${EXE} --batch --csv batch.csv good.prm bad.prm
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE out
                ERROR_VARIABLE err WORKING_DIRECTORY ${WORK_DIR})
message(STATUS "exit code ${exit_code}\n${out}${err}")
if(exit_code EQUAL 0)
  message(FATAL_ERROR "a batch with a failed case must exit non-zero")
endif()
if(NOT err MATCHES "bad.prm")
  message(FATAL_ERROR "the failed case is not named on stderr")
endif()
if(NOT EXISTS ${WORK_DIR}/batch.csv)
  message(FATAL_ERROR "no batch.csv for the case that succeeded")
endif()
file(READ ${WORK_DIR}/batch.csv csv)
if(NOT csv MATCHES "good.prm,K_H," OR csv MATCHES "bad.prm")
  message(FATAL_ERROR "batch.csv must hold the good case's rows only")
endif()
# Only failing cases: no CSV, and the earlier one is gone.
execute_process(COMMAND ${EXE} --batch --csv batch.csv bad.prm
                RESULT_VARIABLE exit_code OUTPUT_QUIET ERROR_QUIET
                WORKING_DIRECTORY ${WORK_DIR})
if(exit_code EQUAL 0 OR EXISTS ${WORK_DIR}/batch.csv)
  message(FATAL_ERROR "an all-failed batch must exit non-zero and leave no CSV")
endif()
message(STATUS "4 passed, 0 failed")
