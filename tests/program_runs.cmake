# Whole-program runs of the fourier-ssi executable.

# Bad input: one-line error naming the file/entry, non-zero exit, no output.
# Each tests/prm/bad_*.prm starts with a line "# expect: <regex>".
file(GLOB FSSI_BAD_PRMS ${CMAKE_CURRENT_SOURCE_DIR}/prm/bad_*.prm)
foreach(prm ${FSSI_BAD_PRMS})
  get_filename_component(name ${prm} NAME_WE)
  file(STRINGS ${prm} expect_line LIMIT_COUNT 1 REGEX "^# expect: ")
  string(REGEX REPLACE "^# expect: " "" expected "${expect_line}")
  add_test(NAME input_${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:fourier-ssi> -DPRM=${prm}
            -DEXPECTED=${expected}
            -DOUTPUT_DIR=${CMAKE_CURRENT_BINARY_DIR}/bad_output
            -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_failure.cmake)
  set_tests_properties(input_${name} PROPERTIES RESOURCE_LOCK bad_output)
endforeach()

# The bundled default scene runs and writes its results.
add_test(NAME program_default_scene
  COMMAND fourier-ssi ${CMAKE_SOURCE_DIR}/prm/default.prm
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(program_default_scene PROPERTIES
  PASS_REGULAR_EXPRESSION "results written to")

# The graded FE_Q(4) recipe: K_H within 1e-4 of the converged 10.79910
# (doc/accuracy-vs-time.md) prints as 10.799x or 10.800.
add_test(NAME program_embedded_footing_graded
  COMMAND fourier-ssi ${CMAKE_SOURCE_DIR}/prm/embedded-footing-graded.prm
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(program_embedded_footing_graded PROPERTIES
  PASS_REGULAR_EXPRESSION "K_H = H/\\(G a u\\) = 10\\.(799|800)")

add_test(NAME program_print_parameters COMMAND fourier-ssi --print-parameters)
set_tests_properties(program_print_parameters PROPERTIES
  PASS_REGULAR_EXPRESSION "subsection Materials")

# The nonlinear-interface scene (tensionless disc in a ring) runs and writes
# its load-displacement curve.
add_test(NAME program_disc_gap
  COMMAND fourier-ssi ${CMAKE_SOURCE_DIR}/prm/disc-gap.prm
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(program_disc_gap PROPERTIES
  PASS_REGULAR_EXPRESSION "load-displacement curve written to")

# A load step that does not converge: one line naming Nonlinear interfaces,
# non-zero exit, no result file. Serial only (not a bad_*.prm: under mpirun
# the coupled solve stops earlier with its "not yet: distributed" line).
add_test(NAME input_nonconverging_coulomb_step
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:fourier-ssi>
          -DPRM=${CMAKE_CURRENT_SOURCE_DIR}/prm/nonconverging_coulomb_step.prm
          "-DEXPECTED=Nonlinear interfaces: load step 1 did not converge"
          -DOUTPUT_DIR=${CMAKE_CURRENT_BINARY_DIR}/bad_output
          -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}
          -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_failure.cmake)
set_tests_properties(input_nonconverging_coulomb_step PROPERTIES
  RESOURCE_LOCK bad_output)
