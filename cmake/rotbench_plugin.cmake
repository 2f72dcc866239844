# rotbench_add_scheme(<target> SOURCES <file>...)
#
# Builds out-of-tree schemes as a plug-in for `rotbench --plugin <target>.so`. Each source
# is written as an in-tree scheme is: a kernel and a RegisterScheme<> object. The library
# gets the ABI entry points (cmake/rotbench_plugin_entry.cpp) and hidden visibility, so that its
# registry is its own until rotbench copies the entries after checking the ABI. It is compiled
# with the built-in schemes' optimisation, ROTBENCH_PLUGIN_OPTIMIZATION, whatever the consumer's
# build type, so that its cost compares with theirs; set that variable (a cache entry) to
# something else on purpose, e.g. "-O0;-g" to debug, and rotbench flags the plug-in's build.
function(rotbench_add_scheme target)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "rotbench_add_scheme(${target}): SOURCES is empty")
  endif()
  add_library(${target} MODULE ${ARG_SOURCES} ${ROTBENCH_PLUGIN_ENTRY})
  target_link_libraries(${target} PRIVATE rotbench::scheme_api)
  target_compile_options(${target} PRIVATE ${ROTBENCH_PLUGIN_OPTIMIZATION})
  set_target_properties(${target} PROPERTIES PREFIX "" CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
endfunction()
