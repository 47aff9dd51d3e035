# The measured cost of the long tests (tests/test_costs.txt), so that ctest -j
# starts them first on a fresh clone, which has no timing history: the
# suite's length is then its total over the cores, without one long scene
# run left alone at the end. A directory that defines tests calls
# fssi_apply_test_costs() after its add_test calls (a test's properties can be
# set only in its own directory). Regenerate the table with
# tools/update_test_costs.py.
file(STRINGS ${CMAKE_CURRENT_LIST_DIR}/test_costs.txt FSSI_TEST_COSTS
     REGEX "^[^#]")
function(fssi_apply_test_costs)
  foreach(row ${FSSI_TEST_COSTS})
    string(REPLACE " " ";" fields "${row}")
    list(GET fields 0 name)
    list(GET fields 1 seconds)
    if(TEST ${name})
      set_tests_properties(${name} PROPERTIES COST ${seconds})
    endif()
  endforeach()
endfunction()
