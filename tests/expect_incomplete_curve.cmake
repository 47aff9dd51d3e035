# Run a coupled scene whose path fails after some converged steps and
# require: a non-zero exit, exactly one line on stderr matching EXPECTED,
# the converged steps in load-displacement-incomplete.csv (the name marks
# them) and no results file in OUTPUT_DIR.
# Usage: cmake -DEXE=... -DPRM=... -DEXPECTED=... -DOUTPUT_DIR=... -DWORK_DIR=...
#              -P expect_incomplete_curve.cmake
file(REMOVE_RECURSE ${OUTPUT_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/one_line_error.cmake)
run_expecting_one_line_error()
if(NOT EXISTS ${OUTPUT_DIR}/load-displacement-incomplete.csv)
  message(FATAL_ERROR "the converged steps were not written")
endif()
file(GLOB leftovers ${OUTPUT_DIR}/*)
list(REMOVE_ITEM leftovers ${OUTPUT_DIR}/load-displacement-incomplete.csv)
if(leftovers)
  message(FATAL_ERROR "output that looks like a result left behind: ${leftovers}")
endif()
file(REMOVE_RECURSE ${OUTPUT_DIR})
message(STATUS "1 passed, 0 failed")
