# Run the fourier-ssi executable on a bad .prm and require: non-zero exit,
# exactly one line on stderr matching EXPECTED, and no results file (nor the
# folder itself) left in OUTPUT_DIR. Usage: cmake -DEXE=... -DPRM=... -DEXPECTED=... -DOUTPUT_DIR=...
#                          -P expect_failure.cmake
file(REMOVE_RECURSE ${OUTPUT_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/one_line_error.cmake)
run_expecting_one_line_error()
file(GLOB leftovers ${OUTPUT_DIR}/*)
if(leftovers)
  message(FATAL_ERROR "partial output left behind: ${leftovers}")
endif()
# Nor an empty output folder the failed run created (README: no output).
if(EXISTS ${OUTPUT_DIR})
  message(FATAL_ERROR "the failed run left its output folder ${OUTPUT_DIR}")
endif()
message(STATUS "1 passed, 0 failed")
