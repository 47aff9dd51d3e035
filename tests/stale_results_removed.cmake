# A run that fails never leaves a result that looks like its own: every file
# an earlier run wrote into the output folder is gone after a later run into
# the same folder fails, whether it fails while solving or its input is
# refused before anything is solved; the user's own files in the folder
# stay. Checked for every writer: a linear scene (per-harmonic VTU, linear
# interface tractions, Lines 3D, revolved 3D VTU), a coulomb interface
# (load-displacement, interface state CSV and 3D VTU, per-harmonic VTU of the
# last step), plastic soil, plastic soil with soil-reaction curves, a renamed
# Results file, a leftover temporary file
# of an interrupted run, and a --batch case.
# Each good run must first write the files listed for it (so that a writer
# that stops writing cannot pass for one whose files were removed).
# Usage: cmake -DEXE=... -DSOURCE_DIR=... -DWORK_DIR=... -P stale_results_removed.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(n_passed 0)

# Runs `prm` (in WORK_DIR); `expect` is "ok" or "fail".
function(run_prm prm expect)
  execute_process(COMMAND ${EXE} ${prm} RESULT_VARIABLE exit_code
                  OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY ${WORK_DIR})
  if(expect STREQUAL "ok" AND NOT exit_code EQUAL 0)
    message(FATAL_ERROR "${prm} must succeed: ${err}")
  elseif(expect STREQUAL "fail" AND exit_code EQUAL 0)
    message(FATAL_ERROR "${prm} must fail")
  endif()
  message(STATUS "${prm}: exit code ${exit_code} ${err}")
endfunction()

# The good run `good` writes every file of `expected` into WORK_DIR/out,
# beside the user's notes.txt; then each bad prm of the list `bads`, run
# after the good run's folder is restored, leaves none of them.
function(check_removed good expected bads)
  file(REMOVE_RECURSE ${WORK_DIR}/out ${WORK_DIR}/saved)
  file(MAKE_DIRECTORY ${WORK_DIR}/out)
  file(WRITE ${WORK_DIR}/out/notes.txt "the user's own file\n")
  run_prm(${good} ok)
  file(GLOB written RELATIVE ${WORK_DIR}/out ${WORK_DIR}/out/*)
  foreach(pattern ${expected})
    file(GLOB found ${WORK_DIR}/out/${pattern})
    if(NOT found)
      message(FATAL_ERROR "${good} did not write ${pattern} (wrote ${written})")
    endif()
  endforeach()
  # An interrupted earlier run's part (AtomicFile's temporary name).
  file(WRITE ${WORK_DIR}/out/.results.csv.partial "part")
  file(COPY ${WORK_DIR}/out DESTINATION ${WORK_DIR}/saved)
  foreach(bad ${bads})
    file(REMOVE_RECURSE ${WORK_DIR}/out)
    file(COPY ${WORK_DIR}/saved/out DESTINATION ${WORK_DIR})
    run_prm(${bad} fail)
    file(GLOB left RELATIVE ${WORK_DIR}/out ${WORK_DIR}/out/* ${WORK_DIR}/out/.*)
    if(NOT left STREQUAL "notes.txt")
      message(FATAL_ERROR "after ${good} then ${bad}, the folder holds "
                          "'${left}' (expected the user's notes.txt only)")
    endif()
    math(EXPR n_passed "${n_passed} + 1")
  endforeach()
  set(n_passed ${n_passed} PARENT_SCOPE)
endfunction()

# Writes WORK_DIR/<name>.prm: the text `scene` and then `extra`.
function(write_prm name scene extra)
  file(WRITE ${WORK_DIR}/${name}.prm "${scene}\n${extra}\n")
endfunction()

set(output "subsection Output
  set Directory = out
  set Write vtu = true
  set Write interface tractions = true
  set Lines 3D = 0.5, -1 -> 5, -1 : 4
  set Write 3D vtu = true
end")

# 1. Linear: the scene of tests/prm/bad_failure_after_vtu.prm, which runs with
#    a rough interface and, as shipped (smooth under H), fails after the
#    n = 0 VTU is written.
file(READ ${SOURCE_DIR}/tests/prm/bad_failure_after_vtu.prm linear)
write_prm(linear "${linear}" "${output}
subsection Interfaces
  set Interfaces = 5: rough
end")
write_prm(linear_fails_solving "${linear}" "${output}")
write_prm(linear_unknown_entry "${linear}" "${output}
subsection Interfaces
  set Interfaces = 5: rough
end
subsection Output
  set Frobnicate = 1
end")
write_prm(linear_negative_modulus "${linear}" "${output}
subsection Interfaces
  set Interfaces = 5: rough
end
subsection Materials
  set Materials = 0: G=-1000, nu=0.3; 1: G=1e6, nu=0.2
end")
write_prm(linear_empty_results_file "${linear}" "${output}
subsection Interfaces
  set Interfaces = 5: rough
end
subsection Output
  set Results file =
end")
# A failing run that names its results otherwise: the earlier results.csv
# goes too.
write_prm(linear_renamed_fails "${linear}" "${output}
subsection Output
  set Results file = other.csv
end")
check_removed(linear.prm
  "results.csv;solution-n0-symmetric-cycle0.vtu;solution-n1-symmetric-cycle0.vtu;interface-5-n1-symmetric-cycle0.csv;lines-3d.csv;solution-3d.vtu"
  "linear_fails_solving.prm;linear_unknown_entry.prm;linear_negative_modulus.prm;linear_empty_results_file.prm;linear_renamed_fails.prm")

# 1b. Files the parameter reader cannot parse at all: the output folder is
#     found by a light scan of their lines, so the earlier results go too.
set(rough "subsection Interfaces
  set Interfaces = 5: rough
end")
write_prm(unparsable_missing_end "${linear}" "${output}
subsection Interfaces
  set Interfaces = 5: rough")
write_prm(unparsable_extra_end "${linear}" "${output}\n${rough}\nend")
write_prm(unparsable_set_without_equals "${linear}" "${output}
subsection Interfaces
  set Interfaces 5: rough
end")
# A line continued by a trailing backslash swallows the end after it.
write_prm(unparsable_trailing_backslash "${linear}" "${output}
subsection Interfaces
  set Interfaces = 5: rough \\
end")
# A NUL byte inside, and the whole file in UTF-16 (cmake writes neither).
execute_process(COMMAND /usr/bin/python3 -c
  "import sys; t = open(sys.argv[1]).read(); open(sys.argv[2], 'w').write(t.replace('end', 'e\\0nd', 1)); open(sys.argv[3], 'w', encoding='utf-16').write(t)"
  ${WORK_DIR}/linear.prm ${WORK_DIR}/unparsable_nul_byte.prm
  ${WORK_DIR}/unparsable_utf16.prm)
# A UTF-8 byte-order mark before a refused file's first line, the one
# that opens its Output subsection.
execute_process(COMMAND /usr/bin/python3 -c
  "import sys; open(sys.argv[1], 'w', encoding='utf-8-sig').write('subsection Output\\n  set Directory = out\\n  set Frobnicate = 1\\nend\\n')"
  ${WORK_DIR}/refused_byte_order_mark.prm)
check_removed(linear.prm "results.csv;solution-3d.vtu"
  "unparsable_missing_end.prm;unparsable_extra_end.prm;unparsable_set_without_equals.prm;unparsable_trailing_backslash.prm;unparsable_nul_byte.prm;unparsable_utf16.prm;refused_byte_order_mark.prm")

# 2. A renamed Results file of the earlier run.
write_prm(linear_renamed "${linear}" "${output}
subsection Interfaces
  set Interfaces = 5: rough
end
subsection Output
  set Results file = other.csv
end")
write_prm(linear_renamed_refused "${linear}" "${output}
subsection Output
  set Results file = other.csv
end
subsection Materials
  set Materials = 0: G=-1000, nu=0.3; 1: G=1e6, nu=0.2
end")
check_removed(linear_renamed.prm "other.csv" "linear_renamed_refused.prm")

# 3. A coulomb interface (the disc of tests/prm/nonconverging_coulomb_step.prm
#    with enough iterations to converge).
file(READ ${SOURCE_DIR}/tests/prm/nonconverging_coulomb_step.prm coulomb)
set(converging "subsection Load path
  set Load steps = 2
  set Maximum iterations = 60
end")
set(coulomb_output "subsection Output
  set Directory = out
  set Write vtu = true
  set Lines 3D = 0.6, 0 -> 5, 0 : 4
  set Write 3D vtu = true
end")
write_prm(coulomb "${coulomb}" "${converging}\n${coulomb_output}")
write_prm(coulomb_fails_solving "${coulomb}" "${coulomb_output}")
write_prm(coulomb_phi_90 "${coulomb}" "${converging}\n${coulomb_output}
subsection Interfaces
  set Interfaces = 5: coulomb, kn=1e6, ks=1e6, c=0, phi=90, sigma_t=0
end")
write_prm(coulomb_control_foo "${coulomb}" "${converging}\n${coulomb_output}
subsection Load path
  set Control = foo
end")
check_removed(coulomb.prm
  "results.csv;load-displacement.csv;interface-state.csv;interface-state-3d.vtu;solution-n0-symmetric-cycle0.vtu;solution-n2-symmetric-cycle0.vtu;lines-3d.csv;solution-3d.vtu"
  "coulomb_fails_solving.prm;coulomb_phi_90.prm;coulomb_control_foo.prm")

# 4. Plastic soil: prm/footing-capacity.prm cut to two steps.
file(READ ${SOURCE_DIR}/prm/footing-capacity.prm plastic)
set(plastic_output "subsection Load path
  set Load steps = 2
  set Target = -0.01
end
subsection Output
  set Directory = out
  set Write vtu = true
end")
write_prm(plastic "${plastic}" "${plastic_output}")
write_prm(plastic_su_negative "${plastic}" "${plastic_output}
subsection Soil plasticity
  set Laws = 0: tresca, su=-1
end")
check_removed(plastic.prm
  "results.csv;load-displacement.csv;solution-n0-symmetric-cycle0.vtu"
  "plastic_su_negative.prm")

# 4b. Plastic soil with soil-reaction curves: prm/pile-free-head.prm on a
#     coarse mesh, n <= 1, two steps; refused: a depth below the pile's toe
#     (found once the mesh is known) and an entry that is not a list.
file(READ ${SOURCE_DIR}/prm/pile-free-head.prm pile)
set(pile_output "subsection Discretization
  set Harmonics = 0, 1
end
subsection Mesh
  set R cells = 1, 6
  set R growth = 1, 1.5
  set Z cells = 1, 4
end
subsection Load path
  set Theta samples = 8
  set Load steps = 2
  set Target = 0.02
end
subsection Output
  set Directory = out
  set Write vtu = false
  set Soil reaction depths = 2, 8
end")
write_prm(pile_curves "${pile}" "${pile_output}")
write_prm(pile_curves_too_deep "${pile}" "${pile_output}
subsection Output
  set Soil reaction depths = 2, 12
end")
write_prm(pile_curves_not_a_list "${pile}" "${pile_output}
subsection Output
  set Soil reaction depths = 2 m
end")
check_removed(pile_curves.prm
  "results.csv;load-displacement.csv;soil-reaction-curves.csv"
  "pile_curves_too_deep.prm;pile_curves_not_a_list.prm")

# 5. A --batch case: a refused case removes its folder's earlier results as
#    a single run does.
file(REMOVE_RECURSE ${WORK_DIR}/out)
file(MAKE_DIRECTORY ${WORK_DIR}/out)
execute_process(COMMAND ${EXE} --batch --csv batch.csv linear.prm
                RESULT_VARIABLE exit_code OUTPUT_QUIET ERROR_QUIET
                WORKING_DIRECTORY ${WORK_DIR})
if(NOT exit_code EQUAL 0 OR NOT EXISTS ${WORK_DIR}/out/results.csv OR
   NOT EXISTS ${WORK_DIR}/batch.csv)
  message(FATAL_ERROR "the good batch must succeed and write its results")
endif()
execute_process(COMMAND ${EXE} --batch --csv batch.csv
                        linear_negative_modulus.prm
                RESULT_VARIABLE exit_code OUTPUT_QUIET ERROR_QUIET
                WORKING_DIRECTORY ${WORK_DIR})
file(GLOB left ${WORK_DIR}/out/* ${WORK_DIR}/batch.csv)
if(exit_code EQUAL 0 OR left)
  message(FATAL_ERROR "a refused batch case must fail and leave no results: "
                      "${left}")
endif()
math(EXPR n_passed "${n_passed} + 1")
message(STATUS "${n_passed} passed, 0 failed")
