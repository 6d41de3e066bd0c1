# `cpack -G DEB` builds the package; unpacked into a temporary root (dpkg -x), its command
# draws a built-in figure from the package's own specs, and a consumer project builds against
# the package's CMake config and runs. Reports skipped (SPLINEFIG-SKIPPED) without dpkg-dev.
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...) in script mode
find_program(DPKG_DEB dpkg-deb)
find_program(DPKG_SHLIBDEPS dpkg-shlibdeps)
if(NOT DPKG_DEB OR NOT DPKG_SHLIBDEPS)
  message("SPLINEFIG-SKIPPED: dpkg-deb or dpkg-shlibdeps (package dpkg-dev) not found")
  return()
endif()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${CMAKE_CPACK_COMMAND} -G DEB --config ${BINARY_DIR}/CPackConfig.cmake -B ${WORK_DIR}/package
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "cpack -G DEB failed: ${rc} ${out}${err}")
endif()
file(GLOB debs ${WORK_DIR}/package/splinefig_*.deb)
list(LENGTH debs count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "cpack made ${count} .deb files: ${debs}")
endif()

# Its control fields: the run-time libraries dpkg-shlibdeps found, and the font.
execute_process(COMMAND ${DPKG_DEB} -f ${debs} Package Version Depends RESULT_VARIABLE rc OUTPUT_VARIABLE control)
if(rc)
  message(FATAL_ERROR "dpkg-deb -f failed: ${rc}")
endif()
foreach(want "Package: splinefig" "libopenimageio" "libstdc\\+\\+6" "libc6" "fonts-dejavu-core" "fonts-dejavu-extra")
  if(NOT control MATCHES "${want}")
    message(FATAL_ERROR "the package's control lacks ${want}:\n${control}")
  endif()
endforeach()

# What it holds.
set(root ${WORK_DIR}/root)
execute_process(COMMAND ${DPKG_DEB} -x ${debs} ${root} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "dpkg-deb -x failed: ${rc}")
endif()
foreach(path usr/bin/splinefig usr/include/splinefig/figures/figure.hpp usr/include/splinefig/testing.hpp
        usr/include/splinefig/version.hpp usr/lib/cmake/splinefig/splinefigConfig.cmake usr/lib/pkgconfig/splinefig.pc
        usr/share/splinefig/specs/bias.toml usr/share/doc/splinefig/README.md usr/share/doc/splinefig/docs/cli.md)
  if(NOT EXISTS ${root}/${path})
    message(FATAL_ERROR "the package has no /${path}")
  endif()
endforeach()
# What building against it needs is recommended: the Debian package that holds each module of
# the installed splinefig.pc's Requires in the package (pkg-config's file for it, owned by the package in
# dpkg's database), and the one holding pkg-config, which the CMake package calls.
execute_process(COMMAND ${DPKG_DEB} -f ${debs} Recommends RESULT_VARIABLE rc OUTPUT_VARIABLE recommends)
string(REGEX REPLACE "^Recommends: " "" recommends "${recommends}")
string(REGEX REPLACE "[ \n]" "" recommends "${recommends}")
string(REPLACE "," ";" recommends "${recommends}")
find_program(PKG_CONFIG_EXE pkg-config)
find_program(DPKG_QUERY dpkg-query)
if(PKG_CONFIG_EXE AND DPKG_QUERY)
  file(STRINGS ${root}/usr/lib/pkgconfig/splinefig.pc requires_line REGEX "^Requires:")
  string(REGEX REPLACE "^Requires: *" "" requires "${requires_line}")
  string(REPLACE " " ";" requires "${requires}")
  set(owned)
  foreach(module IN LISTS requires)
    execute_process(COMMAND ${PKG_CONFIG_EXE} --path ${module} RESULT_VARIABLE rc OUTPUT_VARIABLE pc OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(rc)
      message(FATAL_ERROR "pkg-config finds no ${module}, which splinefig.pc requires")
    endif()
    list(APPEND owned ${pc})
  endforeach()
  list(APPEND owned ${PKG_CONFIG_EXE})
  foreach(file IN LISTS owned)
    execute_process(COMMAND ${DPKG_QUERY} -S ${file} RESULT_VARIABLE rc OUTPUT_VARIABLE owner ERROR_QUIET)
    if(rc)
      message(FATAL_ERROR "no Debian package owns ${file} (dpkg-query -S)")
    endif()
    string(REGEX REPLACE "^([^:,]+).*" "\\1" owner "${owner}")
    if(NOT owner IN_LIST recommends)
      message(FATAL_ERROR "the package does not recommend ${owner}, which holds ${file}: Recommends ${recommends}")
    endif()
  endforeach()
endif()

file(GLOB libs ${root}/usr/lib/libsplinefig_*.a)
list(LENGTH libs count)
if(count LESS 7)
  message(FATAL_ERROR "the package holds only ${count} libraries: ${libs}")
endif()

# No file of the package holds a path of the build or source tree (a program that looked there
# would run whatever anyone able to write into that tree planted).
file(GLOB_RECURSE packaged LIST_DIRECTORIES false ${root}/*)
foreach(f IN LISTS packaged)
  file(STRINGS ${f} hits REGEX "${BINARY_DIR}|${SOURCE_DIR}/")
  if(hits)
    list(GET hits 0 hit)
    message(FATAL_ERROR "the package's ${f} holds a path of the build or source tree: ${hit}")
  endif()
endforeach()

# With a decoy module planted where the build tree used to keep its module and where it keeps
# it now, the packaged program in a root outside the build tree, its own module removed, loads
# neither: it reports the module missing.
string(RANDOM LENGTH 12 tag)
set(outside /tmp/splinefig-deb-outside-${tag})
file(MAKE_DIRECTORY ${outside}/usr/bin)
file(COPY ${root}/usr/bin/splinefig DESTINATION ${outside}/usr/bin)
file(GLOB modules ${BINARY_DIR}/lib*/splinefig/libsplinefig_image_oiio.so)
list(GET modules 0 module)
get_filename_component(module_name ${module} NAME)
set(decoys ${BINARY_DIR}/image/${module_name} ${BINARY_DIR}/${module_name})
foreach(d IN LISTS decoys)
  file(WRITE ${d} "decoy: not a shared object\n")
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_DEBUG=files ${outside}/usr/bin/splinefig diff
  ${SOURCE_DIR}/tests/reference/renderer/fills.png ${SOURCE_DIR}/tests/reference/renderer/fills.png
  WORKING_DIRECTORY ${outside} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(REMOVE ${decoys})
file(REMOVE_RECURSE ${outside})
if(err MATCHES "decoy|${BINARY_DIR}")
  message(FATAL_ERROR "the packaged program looked into the build tree:\n${err}")
endif()
if(NOT rc EQUAL 4 OR NOT err MATCHES "cannot find the image I/O module")
  message(FATAL_ERROR "without its module the packaged program should report it missing (exit 4): ${rc}\n${err}")
endif()

# The unpacked command draws from the package's specs (run outside the source and build trees):
# a title changed in the unpacked copy shows in index.json.
file(READ ${root}/usr/share/splinefig/specs/bias.toml spec)
string(REGEX REPLACE "\ntitle = \"[^\"]*\"" "\ntitle = \"Bias as unpacked\"" spec "${spec}")
file(WRITE ${root}/usr/share/splinefig/specs/bias.toml "${spec}")
execute_process(COMMAND ${root}/usr/bin/splinefig figures --out ${WORK_DIR}/figures --only bias
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc OR NOT EXISTS ${WORK_DIR}/figures/bias.png)
  message(FATAL_ERROR "splinefig figures from the package failed: ${rc} ${out}${err}")
endif()
file(READ ${WORK_DIR}/figures/index.json index)
if(NOT index MATCHES "Bias as unpacked")
  message(FATAL_ERROR "splinefig figures did not draw the package's own bias.toml: ${index}")
endif()

# A consumer project against the package's CMake config.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/consumer
  -DCMAKE_PREFIX_PATH=${root}/usr RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "configuring the consumer against the package failed: ${rc} ${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "building the consumer against the package failed: ${rc} ${out}${err}")
endif()
execute_process(COMMAND ${WORK_DIR}/consumer/consumer ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(rc)
  message(FATAL_ERROR "the consumer built against the package failed: ${rc} ${out}")
endif()
message(STATUS "the package ${debs} installs and runs:\n${control}")
