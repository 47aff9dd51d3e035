# Shared by expect_failure.cmake and expect_unconverged.cmake: run EXE on PRM
# in WORK_DIR and require a non-zero exit with exactly one line on stderr
# matching EXPECTED (the project's promise for every refused or unmet run).
function(run_expecting_one_line_error)
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
    message(FATAL_ERROR "expected a one-line message, got ${n_newlines}+1 lines")
  endif()
  if(NOT err MATCHES "${EXPECTED}")
    message(FATAL_ERROR "message does not match '${EXPECTED}'")
  endif()
endfunction()
