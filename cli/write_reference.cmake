# cmake -DEXE=<splinefig> -DOUT_DIR=<dir> -P write_reference.cmake: the man page and the bash and
# zsh completions, as the built command prints them from its option tables (cli/reference.hpp):
# OUT_DIR/splinefig.1, OUT_DIR/completions/splinefig (bash) and OUT_DIR/completions/_splinefig (zsh).
foreach(item "splinefig.1|--help-man" "completions/splinefig|--completion;bash" "completions/_splinefig|--completion;zsh")
  string(REPLACE "|" ";" item "${item}")
  list(POP_FRONT item file)
  get_filename_component(dir ${OUT_DIR}/${file} DIRECTORY)
  file(MAKE_DIRECTORY ${dir})
  execute_process(COMMAND ${EXE} ${item} OUTPUT_FILE ${OUT_DIR}/${file}.tmp ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    file(REMOVE ${OUT_DIR}/${file}.tmp)
    message(FATAL_ERROR "${EXE} ${item} failed (${rc}): ${err}")
  endif()
  file(RENAME ${OUT_DIR}/${file}.tmp ${OUT_DIR}/${file})
endforeach()
