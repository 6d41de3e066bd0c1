# Installs the built tree into a scratch prefix, moves the prefix elsewhere, keeps only one of
# its built-in specs, and runs the moved `splinefig figures` without SPLINEFIG_SPECS_DIR: it
# must draw exactly the moved prefix's one spec, so it found share/splinefig/specs next to its
# own bin/ and neither the source tree (33 specs) nor the original prefix.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix
  RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()
file(RENAME ${WORK_DIR}/prefix ${WORK_DIR}/moved)
set(specs ${WORK_DIR}/moved/share/splinefig/specs)
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
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=SPLINEFIG_SPECS_DIR
    ${WORK_DIR}/moved/bin/splinefig figures --out ${WORK_DIR}/out
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "the moved splinefig figures failed: ${rc}\n${out}${err}")
endif()
file(GLOB drawn RELATIVE ${WORK_DIR}/out ${WORK_DIR}/out/*.png)
if(NOT drawn STREQUAL "cbasis.png")
  message(FATAL_ERROR "the moved splinefig figures drew [${drawn}], not the moved prefix's one spec [cbasis.png]\n${out}${err}")
endif()
message(STATUS "the moved install drew ${drawn} from ${specs}")
