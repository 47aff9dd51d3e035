# Run a bundled scene with a few entries changed: the variant file starts
# with "# base: prm/<scene>.prm" and "# expect: <regex>" lines, then the
# .prm entries appended to the base scene (later entries win). Requires exit
# code 0 and the regex in the program's output. MPIEXEC (optional) runs it
# under mpirun. Usage: cmake -DEXE=... -DSOURCE_DIR=... -DVARIANT=...
#                          -DWORK_DIR=... [-DMPIEXEC=...] -P run_scene_variant.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
file(STRINGS ${VARIANT} base_line LIMIT_COUNT 1 REGEX "^# base: ")
file(STRINGS ${VARIANT} expect_line LIMIT_COUNT 1 REGEX "^# expect: ")
string(REGEX REPLACE "^# base: " "" base "${base_line}")
string(REGEX REPLACE "^# expect: " "" expected "${expect_line}")
file(READ ${SOURCE_DIR}/${base} text)
file(READ ${VARIANT} variant)
file(WRITE ${WORK_DIR}/scene.prm "${text}\n${variant}
subsection Output
  set Directory = out
end
")
execute_process(COMMAND ${MPIEXEC} ${EXE} scene.prm
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE out
                ERROR_VARIABLE err WORKING_DIRECTORY ${WORK_DIR})
message(STATUS "exit code ${exit_code}\n${out}${err}")
if(NOT exit_code EQUAL 0)
  message(FATAL_ERROR "the run failed (exit code ${exit_code})")
endif()
if(NOT out MATCHES "${expected}")
  message(FATAL_ERROR "output does not match '${expected}'")
endif()
if(NOT EXISTS ${WORK_DIR}/out/results.csv)
  message(FATAL_ERROR "no results.csv written")
endif()
message(STATUS "1 passed, 0 failed")
