# `cpack -G DEB` in the build directory makes splinefig_VERSION_ARCH.deb from the install()
# rules: the command, the static libraries, the headers, the CMake package and splinefig.pc,
# the built-in specs (and whatever else is installed under share/splinefig) and the docs.
# Installed under /usr; the command finds its data relative to its own place, so the package
# also works unpacked anywhere (dpkg -x).

# The user documentation, for the package and for any install.
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME splinefig)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
  "splinefig implements Alvy Ray Smith's Spline Tutorial Notes (1983): cardinal, B-, Beta- and\n"
  "tensioned splines, their basis functions as kernels and antialiasing filters, an exact-area\n"
  "antialiased rasterizer, idiff-compatible image comparison, resampling with spline kernels and\n"
  "TOML figure specs. This package holds the splinefig command, the static libraries, headers,\n"
  "CMake package and pkg-config file, the built-in figure specs and the documentation.")
string(REPLACE ";" "" CPACK_PACKAGE_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION}")
set(CPACK_PACKAGE_CONTACT "splinefig maintainers <splinefig@invalid>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
# The command's run-time libraries, found by dpkg-shlibdeps (package dpkg-dev), after the fonts
# its text is drawn with: DejaVu's core faces (fonts-dejavu-core) and the bold oblique ones
# (fonts-dejavu-extra; the built-in figures' titles are bold oblique).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core, fonts-dejavu-extra")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What building against the libraries needs (their CMake package and splinefig.pc require
# these: SPLINEFIG_DEV_PACKAGES, beside SPLINEFIG_PC_REQUIRES), and the test matchers'
# frameworks. Recommended, not required: the command alone needs none of them.
# The Python package (in /usr/lib/python3/dist-packages) needs python3 with numpy.
set(recommends ${SPLINEFIG_DEV_PACKAGES})
if(SPLINEFIG_PYTHON)
  list(APPEND recommends python3-numpy)
endif()
list(JOIN recommends ", " CPACK_DEBIAN_PACKAGE_RECOMMENDS)
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "catch2, libgtest-dev, libgmock-dev")
set(CPACK_STRIP_FILES ON)
include(CPack)
