# Installs the built tree into a scratch prefix, then configures, builds and runs a tiny
# consumer project that uses find_package(splinefig) and links every exported target.
include(${CMAKE_CURRENT_LIST_DIR}/install_prefix.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/image_module.cmake)
# The README's complete image test (the ```cpp block after "<!-- readme-test: NAME -->").
file(READ ${SOURCE_DIR}/README.md readme)
string(REGEX MATCH "<!-- readme-test: ([a-z_]+\\.cpp) -->\n```cpp\n(.*)" found "${readme}")
if(NOT found)
  message(FATAL_ERROR "README.md has no <!-- readme-test: NAME.cpp --> code block")
endif()
set(readme_name ${CMAKE_MATCH_1})
string(FIND "${CMAKE_MATCH_2}" "\n```" end)
string(SUBSTRING "${CMAKE_MATCH_2}" 0 ${end} readme_code)
file(WRITE ${WORK_DIR}/readme/${readme_name} "${readme_code}\n")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/build
  -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DREADME_TEST_SOURCE=${WORK_DIR}/readme/${readme_name} RESULT_VARIABLE rc)
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
# The README's test: the first run writes its reference, the second compares with it.
get_filename_component(readme_exe ${readme_name} NAME_WE)
foreach(update 1 0)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env SPLINEFIG_UPDATE_REFERENCES=${update} ${WORK_DIR}/build/${readme_exe}
    WORKING_DIRECTORY ${WORK_DIR}/readme RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc)
    message(FATAL_ERROR "the README's ${readme_name} failed (SPLINEFIG_UPDATE_REFERENCES=${update}): ${rc} ${out}${err}")
  endif()
endforeach()
if(NOT EXISTS ${WORK_DIR}/readme/reference/square.png)
  message(FATAL_ERROR "the README's ${readme_name} wrote no reference/square.png")
endif()
message(STATUS "the README's ${readme_name} passed")
