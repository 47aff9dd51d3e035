# Fails if a bundled scene (prm/*.prm) is named by no "# prm:" line of a
# check file in tests/scenes/, or if a check file does not say by its name
# which scene it runs: every check file is <scene>.checks or
# <scene>.<variant>.checks (the variant without a dot), and its "# prm:"
# line is prm/<scene>.prm, an existing bundled scene. A run that changes
# the scene does so with an "# append:" file, so the file name always leads
# to the scene.
# Usage: cmake -DSOURCE_DIR=<source root> -P every_scene_has_checks.cmake
file(GLOB scenes RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/prm/*.prm)
file(GLOB checks ${SOURCE_DIR}/tests/scenes/*.checks)
set(checked "")
set(misnamed "")
foreach(check ${checks})
  get_filename_component(name ${check} NAME)
  file(STRINGS ${check} prm_line LIMIT_COUNT 1 REGEX "^# prm: ")
  string(REGEX REPLACE "^# prm: " "" prm "${prm_line}")
  if(NOT EXISTS ${SOURCE_DIR}/${prm})
    message(FATAL_ERROR "${check}: '# prm: ${prm}' does not exist")
  endif()
  if(name MATCHES "^([^.]+)(\\.[^.]+)?\\.checks$")
    set(scene ${CMAKE_MATCH_1})
    if(NOT prm STREQUAL "prm/${scene}.prm")
      list(APPEND misnamed
           "${name} ('# prm: ${prm}', not prm/${scene}.prm)")
    endif()
  else()
    list(APPEND misnamed "${name} (not <scene>[.<variant>].checks)")
  endif()
  list(APPEND checked ${prm})
endforeach()
if(misnamed)
  string(REPLACE ";" "; " misnamed "${misnamed}")
  message(FATAL_ERROR "check files not named <scene>[.<variant>].checks after "
                      "the prm/<scene>.prm of their '# prm:' line: ${misnamed}")
endif()
set(unchecked "")
foreach(scene ${scenes})
  list(FIND checked ${scene} index)
  if(index EQUAL -1)
    list(APPEND unchecked ${scene})
  endif()
endforeach()
list(LENGTH scenes n_scenes)
list(LENGTH checks n_checks)
if(unchecked)
  message(FATAL_ERROR "bundled scenes without a check file in tests/scenes/: ${unchecked}")
endif()
message("all ${n_scenes} bundled scenes have a check file; all ${n_checks} "
        "check files are named <scene>[.<variant>].checks")
