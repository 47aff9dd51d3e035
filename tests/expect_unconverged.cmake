# Run a scene whose Target accuracy the work bound cannot reach and require:
# a non-zero exit, exactly one line on stderr matching EXPECTED (the
# accuracy reached and the limit), and a results.csv that marks the answer
# as not converged (target_accuracy_reached = 0), so the values a user gets
# can never pass for converged ones.
# GOAL (default K_H) names the goal value whose <GOAL>_converged row must
# be 0; with APPEND, PRM is a bundled scene and APPEND the entries put after
# it (the run reads WORK_DIR/scene.prm).
# Usage: cmake -DEXE=... -DPRM=... [-DAPPEND=...] [-DGOAL=...]
#              -DEXPECTED=... -DWORK_DIR=... -P expect_unconverged.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
if(NOT DEFINED GOAL)
  set(GOAL K_H)
endif()
if(DEFINED APPEND)
  file(READ ${PRM} scene)
  file(READ ${APPEND} appended)
  set(PRM ${WORK_DIR}/scene.prm)
  file(WRITE ${PRM} "${scene}\n${appended}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/one_line_error.cmake)
run_expecting_one_line_error()
if(NOT EXISTS ${WORK_DIR}/out/results.csv)
  message(FATAL_ERROR "no results.csv: the values reached must be written")
endif()
file(READ ${WORK_DIR}/out/results.csv csv)
if(NOT csv MATCHES "\ntarget_accuracy_reached,[^\n]*,0,-")
  message(FATAL_ERROR "results.csv does not mark target_accuracy_reached = 0")
endif()
if(NOT csv MATCHES "\n${GOAL}_converged,[^\n]*,0,-")
  message(FATAL_ERROR "results.csv does not mark ${GOAL}_converged = 0")
endif()
message(STATUS "1 passed, 0 failed")
