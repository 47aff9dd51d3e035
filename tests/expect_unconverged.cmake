# Run a scene whose Target accuracy the work bound cannot reach and require:
# a non-zero exit, exactly one line on stderr matching EXPECTED (the
# accuracy reached and the limit), and a results.csv that marks the answer
# as not converged (target_accuracy_reached = 0), so the values a user gets
# can never pass for converged ones.
# Usage: cmake -DEXE=... -DPRM=... -DEXPECTED=... -DWORK_DIR=...
#              -P expect_unconverged.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/one_line_error.cmake)
run_expecting_one_line_error()
if(NOT EXISTS ${WORK_DIR}/out/results.csv)
  message(FATAL_ERROR "no results.csv: the values reached must be written")
endif()
file(READ ${WORK_DIR}/out/results.csv csv)
if(NOT csv MATCHES "\ntarget_accuracy_reached,[^\n]*,0,-")
  message(FATAL_ERROR "results.csv does not mark target_accuracy_reached = 0")
endif()
if(NOT csv MATCHES "\nK_H_converged,[^\n]*,0,-")
  message(FATAL_ERROR "results.csv does not mark K_H_converged = 0")
endif()
message(STATUS "1 passed, 0 failed")
