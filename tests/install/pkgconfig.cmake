# Installs the built tree into a scratch prefix and builds the find_package consumer's program
# (tests/install/consumer/main.cpp, every library used once) with a plain
#   c++ main.cpp $(pkg-config --cflags --libs splinefig)
# then runs it.
include(${CMAKE_CURRENT_LIST_DIR}/install_prefix.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/image_module.cmake)
file(GLOB_RECURSE pc ${WORK_DIR}/prefix/*/splinefig.pc)
if(NOT pc)
  message(FATAL_ERROR "the install has no splinefig.pc")
endif()
get_filename_component(pcdir ${pc} DIRECTORY)
execute_process(COMMAND ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${pcdir}
    sh -c "${CXX} -O1 -o consumer ${SOURCE_DIR}/tests/install/consumer/main.cpp $(${PKG_CONFIG} --cflags --libs splinefig)"
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "c++ $(pkg-config --cflags --libs splinefig) failed: ${rc}\n${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_DEBUG=files ${WORK_DIR}/consumer ${WORK_DIR}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "the pkg-config consumer failed: ${rc} ${out}${err}")
endif()
message(STATUS "the pkg-config consumer printed: ${out}")
# The installed image I/O module, through the RUNPATH that splinefig.pc's Libs give.
expect_image_module_from("${err}" ${WORK_DIR}/prefix/${LIBDIR}/splinefig)
