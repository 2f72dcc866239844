# The speed tools take plug-ins as the harness does (benchmarks/plugin_args.hpp): a plug-in's
# scheme is listed, counted and benchmarked like a built-in one; a bad plug-in is one line and
# exit 2, and benchmarks/cost.py then writes no cost table; a scheme that crashes, throws or
# hangs is named as not costed and the others are costed.
# Run as: cmake -DBUILD_DIR=... -DPLUGIN=... -DCRASHING=... -DSOURCE_DIR=... -DOUT=... -P speed_tools.cmake
function(expect what code pattern)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc STREQUAL "${code}")
    message(FATAL_ERROR "${what}: exit ${rc}, expected ${code}\n${out}\n${err}")
  endif()
  if(NOT "${out}${err}" MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: output does not match '${pattern}'\n${out}\n${err}")
  endif()
endfunction()

expect("the step driver lists a plug-in's scheme" 0 "zvw_end_velocity"
       ${BUILD_DIR}/rotbench_step_driver --plugin ${PLUGIN} --list)
expect("the step driver steps a plug-in's scheme" 0 "[0-9]"
       ${BUILD_DIR}/rotbench_step_driver --plugin=${PLUGIN} zvw_end_velocity 4 3)
expect("the benchmark runs a plug-in's scheme" 0 "batched/zvw_end_velocity/1000"
       ${BUILD_DIR}/rotbench_bench --plugin ${PLUGIN} --benchmark_filter=^batched/zvw_end_velocity/1000$
       --benchmark_min_time=0.001)
expect("the benchmark refuses a missing plug-in" 2 "^rotbench_bench: [^\n]*no such file\n$"
       ${BUILD_DIR}/rotbench_bench --plugin ${OUT}/missing.so)
expect("the step driver refuses an unknown scheme" 2 "rotbench_step_driver: "
       ${BUILD_DIR}/rotbench_step_driver no_such_scheme 1 1)
file(REMOVE_RECURSE ${OUT})
expect("the cost table refuses a missing plug-in" 2 "^cost: [^\n]*no such file\n$"
       ${SOURCE_DIR}/benchmarks/cost.py --plugin ${OUT}/missing.so ${BUILD_DIR} ${OUT})
if(EXISTS ${OUT}/cost.csv)
  message(FATAL_ERROR "cost.py wrote a cost table after a bad plug-in")
endif()

# valgrind cannot run an AddressSanitizer build (the sanitizer step's): what follows needs it.
if(CXX_FLAGS MATCHES "-fsanitize=address")
  return()
endif()
# Crashing schemes: in callgrind's count (segfault, throw, hang past --timeout) and in the
# benchmark only, after it has timed others. direct is costed all the same. The timeout, 15 s,
# is some five times callgrind's count of direct here on a loaded machine.
file(REMOVE_RECURSE ${OUT})
expect("the cost table costs the others when a scheme crashes, throws or hangs" 0 ""
       ${SOURCE_DIR}/benchmarks/cost.py --quiet --no-public --plugin ${CRASHING} --timeout 15
       --schemes bad_segfault,bad_throw42,bad_hang,bad_in_benchmark ${BUILD_DIR} ${OUT})
file(READ ${OUT}/cost.csv csv)
foreach(expected "\ndirect,1000000,[0-9.]+,[^\n]*,quick,\n"
                 "\nbad_segfault,,[,]*quick,valgrind killed by signal 11\n"
                 "\nbad_throw42,,[,]*quick,valgrind killed by signal 6\n"
                 "\nbad_hang,,[,]*quick,valgrind ran past 15 s\n"
                 "\nbad_in_benchmark,,[,]*quick,rotbench_bench killed by signal 11\n")
  if(NOT csv MATCHES "${expected}")
    message(FATAL_ERROR "cost.csv does not match '${expected}':\n${csv}")
  endif()
endforeach()
