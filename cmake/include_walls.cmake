# Run at build time (cmake/rotbench_layers.cmake) over every file of the layers: an include
# that climbs ("../store/x.hpp") is found next to the file, past the include trees that keep
# a layer from seeing the ones above it, so it is refused here as the compiler refuses an
# absolute one. FILES: the files; STAMP: written when none climbs.
set(climbs FALSE)
foreach(file IN LISTS FILES)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<][^\">]*\\.\\./")
  foreach(line IN LISTS lines)
    file(RELATIVE_PATH shown ${SOURCE_DIR} ${file})
    message(SEND_ERROR "${shown}: `${line}` climbs out of its folder; name the header from its layer's root, "
                       "as in \"harness/store/journal.hpp\" (docs/architecture.md)")
    set(climbs TRUE)
  endforeach()
endforeach()
if(NOT climbs)
  file(TOUCH ${STAMP})
endif()
