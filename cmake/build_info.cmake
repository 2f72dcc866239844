# Run at every build (cmake -P): writes the build-information header with the current
# commit. configure_file rewrites it only when it changes, so nothing rebuilds needlessly.
execute_process(COMMAND git describe --always --dirty --abbrev=12 WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE ROTBENCH_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT ROTBENCH_GIT_COMMIT)
  set(ROTBENCH_GIT_COMMIT unknown)
endif()
configure_file(${SOURCE_DIR}/cmake/build_info.hpp.in ${OUTPUT} @ONLY)
