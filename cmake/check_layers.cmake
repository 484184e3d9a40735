# The layers of verification/, each allowed to include only its own and the layers below it:
#   harness < implementations < properties < comparisons < pages < studies < suite < bench
# (the cli includes any of them). An upward include fails the build, naming the file and the
# include (the layer libraries depend on this check; verification/CMakeLists.txt).
#   cmake -DROOT=<a verification folder> -P check_layers.cmake
# Sources are read from ROOT/src/<layer>/ and headers from ROOT/include/crossdiv/verification/<layer>/;
# a header is named "crossdiv/verification/<layer>/..." and a private one "<layer>/...".
if(NOT ROOT)
  message(FATAL_ERROR "check_layers.cmake: pass -DROOT=<verification folder>")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
set(layers harness implementations properties comparisons pages studies suite bench)
set(violations "")
set(checked 0)
foreach(layer IN LISTS layers)
  list(FIND layers ${layer} own)
  file(GLOB_RECURSE files "${ROOT}/src/${layer}/*.cpp" "${ROOT}/src/${layer}/*.h"
                          "${ROOT}/include/crossdiv/verification/${layer}/*.h")
  foreach(f IN LISTS files)
    math(EXPR checked "${checked} + 1")
    file(STRINGS "${f}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\".*" "\\1" included "${line}")
      string(REGEX REPLACE "^crossdiv/verification/" "" rest "${included}")
      string(REGEX MATCH "^[a-z_]+/" first "${rest}")
      string(REPLACE "/" "" first "${first}")
      list(FIND layers "${first}" theirs)
      if(theirs GREATER own)
        file(RELATIVE_PATH where "${ROOT}" "${f}")
        string(APPEND violations "  ${where} includes ${included}: ${first} is above ${layer}\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(checked EQUAL 0)
  message(FATAL_ERROR "check_layers.cmake: no source under ${ROOT}/src or ${ROOT}/include")
endif()
if(violations)
  string(REPLACE ";" " < " order "${layers}")
  message(FATAL_ERROR "verification/ layers: an include of a higher layer (${order}; each may include "
                      "its own and the ones before it):\n${violations}")
endif()
message(STATUS "verification/ layers: ${checked} files, every include of its own layer or below")
