# Run by CTest (tests/CMakeLists.txt): cmake/include_walls.cmake, the build step that refuses an
# include climbing out of its folder, refuses one and passes the same include named from its
# layer's root. WORK: a scratch folder; SOURCE_DIR: the repository.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/harness/exec)
set(probe ${WORK}/harness/exec/probe.cpp)
foreach(include "../store/journal.hpp" "harness/store/journal.hpp")
  file(WRITE ${probe} "// a probe\n  #  include \"${include}\"\n")
  file(REMOVE ${WORK}/stamp)
  execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${WORK} -DFILES=${probe} -DSTAMP=${WORK}/stamp
                          -P ${SOURCE_DIR}/cmake/include_walls.cmake
                  RESULT_VARIABLE status ERROR_VARIABLE output)
  if(include MATCHES "^\\.\\./")
    if(status EQUAL 0 OR EXISTS ${WORK}/stamp OR NOT output MATCHES "harness/exec/probe.cpp: .*climbs out of[ \n]+its folder")
      message(FATAL_ERROR "`#include \"${include}\"` was not refused (status ${status}):\n${output}")
    endif()
  elseif(NOT status EQUAL 0 OR NOT EXISTS ${WORK}/stamp)
    message(FATAL_ERROR "`#include \"${include}\"` was refused:\n${output}")
  endif()
endforeach()
