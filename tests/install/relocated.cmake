# Installs the built tree into a scratch prefix, moves the prefix elsewhere, checks that no
# installed file names the build or source tree, keeps only one of
# its built-in specs, and runs the moved `splinefig figures` without SPLINEFIG_SPECS_DIR: it
# must draw exactly the moved prefix's one spec, so it found share/splinefig/specs next to its
# own bin/ and neither the source tree (33 specs) nor the original prefix.
include(${CMAKE_CURRENT_LIST_DIR}/install_prefix.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/image_module.cmake)
# Moved out of the build tree too: a program of the build tree may use the source tree's specs.
string(RANDOM LENGTH 8 tag)
set(MOVED ${TMP_DIR}/splinefig-relocated-${tag})
file(REMOVE_RECURSE ${MOVED})
file(RENAME ${WORK_DIR}/prefix ${MOVED})
# No installed file holds a path of the build tree (where the prefix was, too) or of the source
# tree: an installed program that looked there would run what anyone able to write there planted.
string(REGEX REPLACE "([][+.*()^$?|\\])" "\\\\\\1" build_re "${BINARY_DIR}")
string(REGEX REPLACE "([][+.*()^$?|\\])" "\\\\\\1" source_re "${SOURCE_DIR}/")
file(GLOB_RECURSE installed_files LIST_DIRECTORIES false ${MOVED}/*)
foreach(f IN LISTS installed_files)
  file(STRINGS ${f} hits REGEX "${build_re}|${source_re}")
  if(hits)
    list(GET hits 0 hit)
    file(REMOVE_RECURSE ${MOVED})
    message(FATAL_ERROR "the installed ${f} holds a path of the build or source tree: ${hit}")
  endif()
endforeach()
list(LENGTH installed_files count)
message(STATUS "none of the ${count} installed files names the build or source tree")
set(specs ${MOVED}/share/splinefig/specs)
file(GLOB installed RELATIVE ${specs} ${specs}/*.toml)
list(LENGTH installed count)
if(count LESS 2)
  message(FATAL_ERROR "the install holds ${count} built-in specs in ${specs}")
endif()
foreach(spec ${installed})
  if(NOT spec STREQUAL "cbasis.toml")
    file(REMOVE ${specs}/${spec})
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=SPLINEFIG_SPECS_DIR LD_DEBUG=files
    ${MOVED}/bin/splinefig figures --format png,exr --out ${WORK_DIR}/out
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "the moved splinefig figures failed: ${rc}\n${out}${err}")
endif()
# It wrote its EXR through the moved install's image I/O module, found next to its own bin/
# (PNG is written by libpng, without the module).
expect_image_module_from("${err}" ${MOVED}/${LIBDIR}/splinefig)
string(REGEX REPLACE "[^\n]*[0-9]+:\t[^\n]*\n" "" err "${err}")  # the loader's lines
file(GLOB drawn RELATIVE ${WORK_DIR}/out ${WORK_DIR}/out/*.png)
if(NOT drawn STREQUAL "cbasis.png")
  file(REMOVE_RECURSE ${MOVED})
  message(FATAL_ERROR "the moved splinefig figures drew [${drawn}], not the moved prefix's one spec [cbasis.png]\n${out}${err}")
endif()
message(STATUS "the moved install drew ${drawn} from ${specs}")
# Without its specs it says so and draws nothing, rather than reading the source tree's (unless
# something is installed at the configured prefix, its last resort).
file(REMOVE_RECURSE ${specs})
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=SPLINEFIG_SPECS_DIR
    ${MOVED}/bin/splinefig figures --format png,exr --out ${WORK_DIR}/out2
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(REMOVE_RECURSE ${MOVED})
if(NOT EXISTS ${INSTALLED_SPECS_DIR})
  if(NOT rc OR NOT err MATCHES "cannot find the built-in figure specs")
    message(FATAL_ERROR "without its specs the moved splinefig figures exited ${rc}: ${out}${err}")
  endif()
  if(EXISTS ${WORK_DIR}/out2/cbasis.png)
    message(FATAL_ERROR "without its specs the moved splinefig figures still drew figures")
  endif()
else()
  message(STATUS "SPLINEFIG-SKIPPED: the specs installed at ${INSTALLED_SPECS_DIR} hide the case without specs")
endif()
