# rotbench_add_scheme(<target> SOURCES <file>...)
#
# Builds out-of-tree schemes as a plug-in for `rotbench --plugin <target>.so`. Each source
# is written as an in-tree scheme is: a kernel and a RegisterScheme<> object. The library
# gets the ABI entry points (cmake/rotbench_plugin_entry.cpp) and hidden visibility, so that its
# registry is its own until rotbench copies the entries after checking the ABI.
function(rotbench_add_scheme target)
  cmake_parse_arguments(ARG "" "" "SOURCES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "rotbench_add_scheme(${target}): SOURCES is empty")
  endif()
  add_library(${target} MODULE ${ARG_SOURCES} ${ROTBENCH_PLUGIN_ENTRY})
  target_link_libraries(${target} PRIVATE rotbench::scheme_api)
  set_target_properties(${target} PROPERTIES PREFIX "" CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
endfunction()
