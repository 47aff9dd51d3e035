# Whole-program runs of the fourier-ssi executable.

# The program on PRM stops with one line matching EXPECTED, a non-zero exit
# and no result file (SCRIPT, default expect_failure.cmake; with
# expect_incomplete_curve.cmake the converged steps' curve is kept).
function(fssi_expect_failure name prm expected)
  set(script expect_failure.cmake)
  if(ARGN)
    set(script ${ARGN})
  endif()
  add_test(NAME input_${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:fourier-ssi> -DPRM=${prm}
            "-DEXPECTED=${expected}"
            -DOUTPUT_DIR=${CMAKE_CURRENT_BINARY_DIR}/bad_output
            -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/${script})
  set_tests_properties(input_${name} PROPERTIES RESOURCE_LOCK bad_output)
endfunction()

# A Target accuracy out of reach: one line matching EXPECTED, exit 3, the
# results written but marked not converged (run in WORK_DIR; further
# arguments: more -D definitions of expect_unconverged.cmake, APPEND, GOAL).
function(fssi_expect_unconverged name prm work_dir expected)
  add_test(NAME program_${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:fourier-ssi> -DPRM=${prm}
            ${ARGN} "-DEXPECTED=${expected}"
            -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/${work_dir}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_unconverged.cmake)
endfunction()

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

# The bundled scenes run as tests in tests/scenes/, checked against their
# references.

# A directory given as the .prm (an ifstream would read it as an empty file
# and run the default of every entry).
fssi_expect_failure(prm_is_a_directory
  ${CMAKE_CURRENT_SOURCE_DIR}/prm
  "prm: is a directory, not a parameter file")

# A .prm that starts with a UTF-8 byte-order mark runs like any other.
add_test(NAME program_prm_with_byte_order_mark
  COMMAND fourier-ssi ${CMAKE_CURRENT_SOURCE_DIR}/prm/bom_header.prm
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(program_prm_with_byte_order_mark PROPERTIES
  PASS_REGULAR_EXPRESSION "results written to")


add_test(NAME program_print_parameters COMMAND fourier-ssi --print-parameters)
set_tests_properties(program_print_parameters PROPERTIES
  PASS_REGULAR_EXPRESSION "subsection Materials")

# With a file it prints that file's values (it used to ignore the file and
# print the defaults): disc-gap's tensionless coulomb law, not the default
# interface list.
add_test(NAME program_print_parameters_of_file
  COMMAND fourier-ssi --print-parameters ${CMAKE_SOURCE_DIR}/prm/disc-gap.prm)
set_tests_properties(program_print_parameters_of_file PROPERTIES
  PASS_REGULAR_EXPRESSION "set Interfaces *= 5: coulomb, kn=1e6, ks=1e6, c=0, phi=0, sigma_t=0")

# The --interface-matrix command of the front end: a straight vertical face at
# r = 0.5 of length 1, p = 2, n = 1, kn = ks = 1e10. Its first diagonal entry
# is pi r kn L 4/30 = 2.0943951024e9 (the theta weight pi of n = 1 times the
# consistent quadratic "mass" matrix L/30 [4 2 -1; 2 16 2; -1 2 4]).
add_test(NAME program_interface_matrix_closed_form
  COMMAND fourier-ssi --interface-matrix p=2 n=1 family=sym r=0.5,0.5,0.5
          z=0,0.5,1 kn=1e10 ks=1e10)
set_tests_properties(program_interface_matrix_closed_form PROPERTIES
  PASS_REGULAR_EXPRESSION "A0\\.r +2\\.0943951024e\\+09")

# The nonlinear-interface scene (tensionless disc in a ring) runs and writes
# its load-displacement curve.
add_test(NAME program_disc_gap
  COMMAND fourier-ssi ${CMAKE_SOURCE_DIR}/prm/disc-gap.prm
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(program_disc_gap PROPERTIES
  PASS_REGULAR_EXPRESSION "load-displacement curve written to")

# A load step that does not converge: one line naming Load path,
# non-zero exit, no result file. Not a bad_*.prm (those also run under
# mpirun): its 2-rank variant is tests/mpi/ mpi_input_nonconverging_coulomb_step.
fssi_expect_failure(nonconverging_coulomb_step
  ${CMAKE_CURRENT_SOURCE_DIR}/prm/nonconverging_coulomb_step.prm
  "Load path: load step 1 of 1 \\(after 1 cuts\\) did not converge")

# Discretization/Target accuracy out of the reach of Adaptivity/Maximum DoFs:
# one line with the accuracy reached and the limit, non-zero exit, and the
# results written but marked not converged.
fssi_expect_unconverged(target_accuracy_unreachable
  ${CMAKE_CURRENT_SOURCE_DIR}/accuracy/unreachable_target.prm
  target_unreachable
  "Discretization/Target accuracy 1e-08 not reached: estimated relative error [0-9.e+-]+ with [0-9]+ DoFs; the next mesh \\(about [0-9]+ DoFs\\) exceeds Adaptivity/Maximum DoFs = 100000")

# The same target with the bound in Mesh/Maximum DoFs: the mesh builder
# refusing a later member of the design is an unmet target (exit 3, results
# marked), not an input error.
fssi_expect_unconverged(target_accuracy_mesh_limit
  ${CMAKE_CURRENT_SOURCE_DIR}/accuracy/unreachable_target_mesh_limit.prm
  target_mesh_limit
  "Discretization/Target accuracy 1e-08 not reached: estimated relative error [0-9.e+-]+ with [0-9]+ DoFs; the next mesh: Mesh/Global refinements: .* above Mesh/Maximum DoFs = 1e\\+05")

# Plastic soil: the capacity of prm/pile-capacity.prm asked to 1e-2, whose
# n <= 8 truncation (2.2e-2) needs the harmonics doubled, with a work bound
# (6 000 DoFs over all harmonics) that doubling would exceed: one line
# naming the truncation and the bound, non-zero exit, results marked (about
# 5 s); and asked to 5e-2 (no doubling needed) with a bound that the second
# mesh exceeds.
fssi_expect_unconverged(capacity_target_harmonics_unreachable
  ${CMAKE_SOURCE_DIR}/prm/pile-capacity.prm
  capacity_target_harmonics
  "Discretization/Target accuracy 0.01 not reached: the harmonic truncation \\(n <= 8\\) alone is [0-9.e+-]+, more than half of it; doubling the harmonics \\(about [0-9]+ DoFs\\) would exceed Adaptivity/Maximum DoFs = 6000"
  -DAPPEND=${CMAKE_CURRENT_SOURCE_DIR}/accuracy/capacity_target_harmonics_bound.prm
  -DGOAL=capacity_H)
fssi_expect_unconverged(capacity_target_dofs_unreachable
  ${CMAKE_SOURCE_DIR}/prm/pile-capacity.prm
  capacity_target_dofs
  "Discretization/Target accuracy 0.05 not reached: estimated relative error of the capacity H unknown \\(one mesh solved\\) with [0-9]+ DoFs \\(all harmonics\\); the next mesh \\(about [0-9]+\\) exceeds Adaptivity/Maximum DoFs = 5000"
  -DAPPEND=${CMAKE_CURRENT_SOURCE_DIR}/accuracy/capacity_target_dofs.prm
  -DGOAL=capacity_H)

# Plastic soil: a load step that does not converge stops with one line
# naming Soil plasticity, non-zero exit, no result file (serial only, as
# the interface case above).
fssi_expect_failure(nonconverging_soil_step
  ${CMAKE_CURRENT_SOURCE_DIR}/prm/nonconverging_soil_step.prm
  "Soil plasticity: load step 1 of 1 \\(after 0 cuts\\) did not converge")

# Mohr-Coulomb limit load from above: the thick cylinder of
# prm/cylinder-mohr-coulomb.prm loaded in one step to 1.02 times its
# closed-form limit pressure cannot converge (no equilibrium exists); the
# scene variant cylinder_mohr_coulomb_below_limit converges at 0.98 times it.
fssi_expect_failure(cylinder_mohr_coulomb_above_limit
  ${CMAKE_CURRENT_SOURCE_DIR}/prm/cylinder_mohr_coulomb_above_limit.prm
  "Soil plasticity: load step 1 of 1 \\(after 0 cuts\\) did not converge")

# Step numbers in messages count the Load steps, not the cut steps: the
# cylinder above its limit in two steps with four cuts fails in step 2 of 2
# after converged cut steps ever closer to the limit ("load step 21" before).
# How many cuts the last attempt had, and whether the step size reached its
# floor, depends on how close to the limit the rounding lets a cut step
# converge (machines differ); the user sees the step, the failure and the
# kept curve. Where the step size reaches its floor first, 2^-(Maximum step
# cuts) of a load step under load control, the line says the loads are at a
# limit, with the same step number.
fssi_expect_failure(step_number_counts_load_steps
  ${CMAKE_CURRENT_SOURCE_DIR}/prm/step_number_counts_load_steps.prm
  "Soil plasticity: load step 2 of 2( \\(after [0-4] cuts[^)]*\\) did not converge in 3000 iterations|: the loads are carried only up to 0\\.9[0-9]* of their full value: the steps converge ever closer to a limit load[^;]*;[^;]*); the [0-9]+ converged steps are kept"
  expect_incomplete_curve.cmake)

# A held load the soil cannot carry (prm/held_loads_beyond_soil_capacity.prm):
# the held stage stops at its limit with one line saying how much of the
# held loads is carried, a non-zero exit and the converged steps' curve
# kept (it used to take steps down to 2^-20 of a load step for minutes).
fssi_expect_failure(held_loads_beyond_soil_capacity
  ${CMAKE_CURRENT_SOURCE_DIR}/prm/held_loads_beyond_soil_capacity.prm
  "Soil plasticity: load step [1-4] of 4 of the held loads: the held loads \\(body force, tractions, held foundation loads\\) are carried only up to 0\\.[0-9]+ of their full value: the steps converge ever closer to a limit load[^;]*; the soil cannot carry them[^;]*; the [0-9]+ converged steps are kept"
  expect_incomplete_curve.cmake)

# A misspelt option is an unknown option, not a parameter file that cannot
# be opened.
fssi_expect_failure(unknown_option
  --frobnicate
  "^fourier-ssi: error: unknown option '--frobnicate' \\(fourier-ssi --help lists the options\\)$")

# A parameter file with a NUL byte (prm/nul_byte.prm: a valid scene whose
# line 4 holds one) is refused; the parser used to stop reading there and
# run the rest at the defaults.
fssi_expect_failure(nul_byte
  ${CMAKE_CURRENT_SOURCE_DIR}/prm/nul_byte.prm
  "nul_byte.prm: line 4 contains a NUL byte: not a text parameter file")

# An output folder that cannot be created gets one line naming the entry
# and the cause, not the file system's exception (prm/output_under_file.prm
# puts it under CTestTestfile.cmake, a file in the tests' working folder).
fssi_expect_failure(output_directory_unwritable
  ${CMAKE_CURRENT_SOURCE_DIR}/prm/output_under_file.prm
  "Output/Directory: 'CTestTestfile.cmake/output' cannot be created: '.*CTestTestfile.cmake' is a file$")

# Cohesionless Mohr-Coulomb soil without Initial stress: warned before the
# path starts (the run itself then fails to converge, as the warning says).
add_test(NAME program_cohesionless_soil_warning
  COMMAND fourier-ssi ${CMAKE_CURRENT_SOURCE_DIR}/prm/cohesionless_soil.prm
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(program_cohesionless_soil_warning PROPERTIES
  PASS_REGULAR_EXPRESSION "warning: Soil plasticity/Laws: material 0: mohr-coulomb with c = 0 and no Initial stress has no strength"
  RESOURCE_LOCK bad_output)
