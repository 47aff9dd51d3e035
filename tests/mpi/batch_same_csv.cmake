# A batch of 3 cases (embedded footing, pile, rough disc; one cycle each) run
# with `fourier-ssi --batch` on 1 and on 2 ranks must write byte-identical
# batch CSVs, holding the stiffness coefficients of the footing and the pile.
# Usage: cmake -DMPIEXEC="mpirun;-np;2;..." -DEXE=... -DSOURCE_DIR=...
#              -DWORK_DIR=... -P batch_same_csv.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(cases "")
set(i 0)
foreach(scene embedded-footing pile disc-rough)
  math(EXPR i "${i} + 1")
  file(READ ${SOURCE_DIR}/prm/${scene}.prm text)
  # A later subsection wins in deal.II's ParameterHandler.
  string(APPEND text "
subsection Discretization
  set Refinement cycles = 1
end
subsection Output
  set Directory = case${i}
  set Write vtu = false
end
")
  file(WRITE ${WORK_DIR}/case${i}.prm "${text}")
  string(APPEND cases "case${i}.prm\n")
endforeach()
file(WRITE ${WORK_DIR}/cases.list "# the batch of this test\n${cases}")

# -np 1 and -np 2: replace the process count of MPIEXEC.
string(REPLACE ";2;" ";1;" mpiexec_1 "${MPIEXEC}")
foreach(n 1 2)
  if(n EQUAL 1)
    set(launcher ${mpiexec_1})
  else()
    set(launcher ${MPIEXEC})
  endif()
  execute_process(COMMAND ${launcher} ${EXE} --batch --csv batch-${n}.csv
                          cases.list
                  RESULT_VARIABLE exit_code OUTPUT_VARIABLE out
                  ERROR_VARIABLE err WORKING_DIRECTORY ${WORK_DIR})
  message(STATUS "${n} rank(s): exit code ${exit_code}\n${out}${err}")
  if(NOT exit_code EQUAL 0)
    message(FATAL_ERROR "batch on ${n} rank(s) failed")
  endif()
endforeach()

file(READ ${WORK_DIR}/batch-1.csv csv1)
file(STRINGS ${WORK_DIR}/batch-1.csv k_rows REGEX "^case[12]\\.prm,K_(H|M|MH),")
list(LENGTH k_rows n_k_rows)
if(NOT n_k_rows EQUAL 6)
  message(FATAL_ERROR "expected K_H, K_M, K_MH of cases 1 and 2 in the batch "
                      "CSV, found ${n_k_rows} rows:\n${csv1}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
                        ${WORK_DIR}/batch-1.csv ${WORK_DIR}/batch-2.csv
                RESULT_VARIABLE differ)
if(differ)
  file(READ ${WORK_DIR}/batch-2.csv csv2)
  message(FATAL_ERROR "batch CSVs differ:\n1 rank:\n${csv1}\n2 ranks:\n${csv2}")
endif()
message(STATUS "batch CSVs identical (${n_k_rows} stiffness rows); 1 passed, 0 failed")
