# A batch whose cases write to one Output/Directory is refused before any
# case runs: one line naming both files and the folder, a non-zero exit, no
# batch CSV and no case output (each run would remove the other's results).
# Usage: cmake -DEXE=... -DSOURCE_DIR=... -DWORK_DIR=... -P batch_output_folders_distinct.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
file(READ ${SOURCE_DIR}/prm/embedded-footing-graded.prm scene)
foreach(name a b)
  file(WRITE ${WORK_DIR}/${name}.prm "${scene}
subsection Output
  set Directory = shared/./
  set Write vtu = false
end
")
endforeach()
# The same folder spelled differently still collides.
file(READ ${WORK_DIR}/b.prm b)
string(REPLACE "shared/./" "shared" b "${b}")
file(WRITE ${WORK_DIR}/b.prm "${b}")
execute_process(COMMAND ${EXE} --batch --csv batch.csv a.prm b.prm
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE out
                ERROR_VARIABLE err WORKING_DIRECTORY ${WORK_DIR})
message(STATUS "exit code ${exit_code}\n${out}${err}")
set(failed 0)
if(exit_code EQUAL 0)
  message(SEND_ERROR "FAIL a batch with two cases in one folder must exit non-zero")
  math(EXPR failed "${failed} + 1")
endif()
if(NOT err MATCHES "--batch: a.prm and b.prm both write to Output/Directory 'shared")
  message(SEND_ERROR "FAIL the line must name both cases and the folder")
  math(EXPR failed "${failed} + 1")
endif()
string(REGEX MATCHALL "\n" lines "${err}")
list(LENGTH lines n_lines)
if(NOT n_lines EQUAL 1)
  message(SEND_ERROR "FAIL one line on stderr, got ${n_lines}")
  math(EXPR failed "${failed} + 1")
endif()
if(EXISTS ${WORK_DIR}/batch.csv OR EXISTS ${WORK_DIR}/shared/results.csv)
  message(SEND_ERROR "FAIL nothing may run: a batch CSV or a case result exists")
  math(EXPR failed "${failed} + 1")
endif()
message(STATUS "${failed} failed")
