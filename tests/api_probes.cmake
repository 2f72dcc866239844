# Run by CTest (tests/CMakeLists.txt): builds each scheme-API probe, TARGET=EXPECTED. EXPECTED
# "builds": it must build; otherwise it must fail to build with EXPECTED (a regular
# expression) in the compiler's output, so that it fails for the reason it was written for.
foreach(probe IN LISTS PROBES)
  string(FIND "${probe}" "=" at)
  string(SUBSTRING "${probe}" 0 ${at} target)
  math(EXPR at "${at} + 1")
  string(SUBSTRING "${probe}" ${at} -1 expected)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${target}
                  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(expected STREQUAL "builds")
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${target} must build, but did not:\n${output}")
    endif()
  elseif(status EQUAL 0)
    message(FATAL_ERROR "${target} must not build, but did")
  elseif(NOT output MATCHES "${expected}")
    message(FATAL_ERROR "${target} failed, but not for '${expected}':\n${output}")
  endif()
  message(STATUS "${target}: ${expected}")
endforeach()
