# Run the fourier-ssi executable on a bad .prm and require: non-zero exit,
# exactly one line on stderr matching EXPECTED, and no results file (nor the
# folder itself) left in OUTPUT_DIR. Usage: cmake -DEXE=... -DPRM=... -DEXPECTED=... -DOUTPUT_DIR=...
#                          -P expect_failure.cmake
file(REMOVE_RECURSE ${OUTPUT_DIR})
execute_process(COMMAND ${EXE} ${PRM}
                RESULT_VARIABLE exit_code
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err
                WORKING_DIRECTORY ${WORK_DIR})
string(STRIP "${err}" err)
message(STATUS "exit code ${exit_code}, stderr: ${err}")
if(exit_code EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit code")
endif()
string(REGEX MATCHALL "\n" newlines "${err}")
list(LENGTH newlines n_newlines)
if(NOT n_newlines EQUAL 0)
  message(FATAL_ERROR "expected a one-line error, got ${n_newlines}+1 lines")
endif()
if(NOT err MATCHES "${EXPECTED}")
  message(FATAL_ERROR "error message does not match '${EXPECTED}'")
endif()
file(GLOB leftovers ${OUTPUT_DIR}/*)
if(leftovers)
  message(FATAL_ERROR "partial output left behind: ${leftovers}")
endif()
# Nor an empty output folder the failed run created (README: no output).
if(EXISTS ${OUTPUT_DIR})
  message(FATAL_ERROR "the failed run left its output folder ${OUTPUT_DIR}")
endif()
message(STATUS "1 passed, 0 failed")
