# Installs the built tree into a scratch prefix, then configures, builds and runs a tiny
# consumer project that uses find_package(splinefig) and links every exported target.
include(${CMAKE_CURRENT_LIST_DIR}/install_prefix.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/image_module.cmake)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/build
  -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_DEBUG=files ${WORK_DIR}/build/consumer ${WORK_DIR}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "the consumer failed: ${rc} ${out}")
endif()
message(STATUS "consumer printed: ${out}")
# Its PNG round trip loaded the installed image I/O module (through the RUNPATH the package
# config gives programs linking splinefig::image).
expect_image_module_from("${err}" ${WORK_DIR}/prefix/${LIBDIR}/splinefig)
execute_process(COMMAND ${WORK_DIR}/build/matcher_test WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
  ENCODING UTF-8)
if(rc)
  message(FATAL_ERROR "the consumer's Catch2 matcher test failed: ${rc} ${out}${err}")
endif()
message(STATUS "the consumer's Catch2 matcher test printed: ${out}")
