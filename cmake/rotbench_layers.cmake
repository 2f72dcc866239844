# The layers of rotbench (docs/architecture.md), bottom up:
#   schemes -> references -> scenes -> core -> store -> exec -> analysis -> reports -> cli
# Each is an OBJECT library that sees, through its include tree, only its own folders and those
# of the layers it links. An include tree is a directory of the build holding symbolic links
# to the folders a layer owns, so that `#include "harness/..."` in a scheme finds nothing and
# does not build (tests/layering checks it).

set(ROTBENCH_LAYERS_DIR ${CMAKE_BINARY_DIR}/layers)

# rotbench_include_tree(<tree> <folder>...): links each source folder into layers/<tree>.
function(rotbench_include_tree tree)
  foreach(folder IN LISTS ARGN)
    set(link ${ROTBENCH_LAYERS_DIR}/${tree}/${folder})
    get_filename_component(parent ${link} DIRECTORY)
    file(MAKE_DIRECTORY ${parent})
    if(NOT IS_SYMLINK ${link})
      file(CREATE_LINK ${CMAKE_SOURCE_DIR}/${folder} ${link} SYMBOLIC)
    endif()
  endforeach()
endfunction()

# Unity builds (docs/performance.md): the files of a layer that computes nothing per step (and of
# the tests) are compiled 16 to a batch, each batch one translation unit, so that the libraries'
# headers are parsed and their templates instantiated once a batch rather than once a file.
# File-local names must therefore differ within such a layer: two alike clash, or one file's
# overload is chosen in another. Not for the numerical layers: in one large unit GCC inlined less,
# and `direct` took twice the time per step. ROTBENCH_UNITY=OFF compiles every file alone, as the
# sanitize preset does, which shows a file that does not compile by itself.
option(ROTBENCH_UNITY "compile each layer and the tests in unity batches" ON)
function(rotbench_unity target)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ${ROTBENCH_UNITY} UNITY_BUILD_BATCH_SIZE 16)
endfunction()

# rotbench_layer(<target> TREE <tree> FOLDERS <folder>... [SOURCES_IN <folder>...] [LINKS <target>...] [UNITY]):
# an OBJECT library of every .cpp in the folders (or in SOURCES_IN, subfolders included),
# seeing its own tree and those of the layers it links; UNITY: compiled in unity batches.
function(rotbench_layer target)
  cmake_parse_arguments(ARG "UNITY" "TREE" "FOLDERS;SOURCES_IN;LINKS" ${ARGN})
  rotbench_include_tree(${ARG_TREE} ${ARG_FOLDERS})
  if(NOT ARG_SOURCES_IN)
    set(ARG_SOURCES_IN ${ARG_FOLDERS})
  endif()
  set(sources)
  foreach(folder IN LISTS ARG_SOURCES_IN)
    file(GLOB found CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${folder}/*.cpp)
    list(APPEND sources ${found})
  endforeach()
  add_library(${target} OBJECT ${sources})
  if(ARG_UNITY)
    rotbench_unity(${target})
  endif()
  target_include_directories(${target} PUBLIC ${ROTBENCH_LAYERS_DIR}/${ARG_TREE})
  target_link_libraries(${target} PUBLIC ${ARG_LINKS})
  # An include that climbs ("../x.hpp") is found beside the file, past the include trees: the
  # build refuses it (cmake/include_walls.cmake), as the compiler refuses an absolute one.
  set(files)
  set(scanned ${ARG_FOLDERS} ${ARG_SOURCES_IN})
  list(REMOVE_DUPLICATES scanned)
  foreach(folder IN LISTS scanned)
    file(GLOB found CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${folder}/*.cpp ${CMAKE_SOURCE_DIR}/${folder}/*.hpp
         ${CMAKE_SOURCE_DIR}/${folder}/*.ipp)
    list(APPEND files ${found})
  endforeach()
  set(stamp ${ROTBENCH_LAYERS_DIR}/${ARG_TREE}.walls)
  add_custom_command(OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} "-DFILES=${files}" -DSTAMP=${stamp}
            -P ${CMAKE_SOURCE_DIR}/cmake/include_walls.cmake
    DEPENDS ${files} ${CMAKE_SOURCE_DIR}/cmake/include_walls.cmake VERBATIM)
  add_custom_target(${target}_walls DEPENDS ${stamp})
  add_dependencies(${target} ${target}_walls)
endfunction()

# Object files are linked only into targets that link their library directly (CMake's rule
# for OBJECT libraries), and the self-registering schemes, scenes and verbs must all be in:
# an executable links every layer it uses.
set(ROTBENCH_ALL_LAYERS rotbench_cli rotbench_reports rotbench_analysis rotbench_exec rotbench_store rotbench_core rotbench_scenes rotbench_references rotbench_schemes)
