# Included by the install tests: expect_image_module_from(OUTPUT DIR) fails unless the dynamic
# loader's account (LD_DEBUG=files) in OUTPUT shows the image I/O module loaded from DIR, i.e.
# the installed program or consumer found the installed module, not the build tree's.
function(expect_image_module_from output dir)
  # "calling init:" names the file the loader found, also for a name looked up in the RUNPATH.
  string(REGEX MATCH "calling init: ([^\n]*libsplinefig_image_oiio[^\n]*)" found "${output}")
  if(NOT found)
    message(FATAL_ERROR "the image I/O module was not loaded (LD_DEBUG=files shows no libsplinefig_image_oiio)")
  endif()
  get_filename_component(loaded_dir ${CMAKE_MATCH_1} DIRECTORY)
  file(REAL_PATH ${loaded_dir} loaded_dir)
  file(REAL_PATH ${dir} dir)
  if(NOT loaded_dir STREQUAL dir)
    message(FATAL_ERROR "the image I/O module was loaded from ${loaded_dir}, not from the install's ${dir}")
  endif()
  message(STATUS "the image I/O module was loaded from ${loaded_dir}")
endfunction()
