# `mpirun -np 2 fourier-ssi scene.prm` (embedded footing, one cycle) must
# succeed, print the stiffness line once (rank 0 only), and write results.csv
# and the parallel VTU output: a .pvtu record naming one .vtu piece per rank.
# Usage: cmake -DMPIEXEC=... -DEXE=... -DSOURCE_DIR=... -DWORK_DIR=...
#              -P program_scene.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
file(READ ${SOURCE_DIR}/prm/embedded-footing.prm text)
string(APPEND text "
subsection Discretization
  set Refinement cycles = 1
end
subsection Output
  set Directory = out
  set Write vtu = true
end
")
file(WRITE ${WORK_DIR}/scene.prm "${text}")
execute_process(COMMAND ${MPIEXEC} ${EXE} scene.prm
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE out
                ERROR_VARIABLE err WORKING_DIRECTORY ${WORK_DIR})
message(STATUS "exit code ${exit_code}\n${out}${err}")
if(NOT exit_code EQUAL 0)
  message(FATAL_ERROR "the 2-rank run failed")
endif()
string(REGEX MATCHALL "K_H = H/\\(G a u\\)" lines "${out}")
list(LENGTH lines n_lines)
if(NOT n_lines EQUAL 1)
  message(FATAL_ERROR "expected one stiffness line (rank 0), got ${n_lines}")
endif()
set(base ${WORK_DIR}/out/solution-n1-symmetric-cycle0)
foreach(file ${WORK_DIR}/out/results.csv ${base}.pvtu ${base}.rank0.vtu
             ${base}.rank1.vtu)
  if(NOT EXISTS ${file})
    message(FATAL_ERROR "missing ${file}")
  endif()
endforeach()
file(READ ${base}.pvtu record)
if(NOT record MATCHES "solution-n1-symmetric-cycle0.rank0.vtu" OR
   NOT record MATCHES "solution-n1-symmetric-cycle0.rank1.vtu")
  message(FATAL_ERROR "the .pvtu record does not name both pieces:\n${record}")
endif()
message(STATUS "1 passed, 0 failed")
