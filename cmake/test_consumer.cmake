# The test of `cmake --install` and find_package(crossdiv): installs this build into a staging
# prefix, builds examples/cmake-consumer against it, runs it, and runs the installed crossdiv.
# cmake -DSOURCE=<source tree> -DBUILD=<build tree> -DWORK=<scratch folder> -DCXX=<compiler> [-DFLAGS=<flags>]
#       -P test_consumer.cmake
file(REMOVE_RECURSE "${WORK}")
set(stage "${WORK}/stage")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${stage}" OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE}/examples/cmake-consumer" -B "${WORK}/consumer"
                        -DCMAKE_PREFIX_PATH=${stage} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX}
                        "-DCMAKE_CXX_FLAGS=${FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${FLAGS}" COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}/consumer" -j2 COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND "${WORK}/consumer/consumer" COMMAND_ERROR_IS_FATAL ANY)
# The installed executable finds its files beside itself, not in this source tree.
execute_process(COMMAND "${stage}/bin/crossdiv" compare bundled:tetrahedron --levels 1 COMMAND_ERROR_IS_FATAL ANY)
foreach(f share/crossdiv/suites/default.suite share/crossdiv/reports/make_report.py share/crossdiv/reports/viewer/viewer.js
          share/crossdiv/adapters/meshlab/meshlab_subdivide.py lib/cmake/crossdiv/crossdivConfig.cmake)
  if(NOT EXISTS "${stage}/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
# The Python module, when built, imports from the installed prefix.
file(GLOB python_module "${stage}/lib/python3/dist-packages/crossdiv*.so")
if(EXISTS "${BUILD}/python")
  if(NOT python_module)
    message(FATAL_ERROR "not installed: the Python module crossdiv in lib/python3/dist-packages")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env "PYTHONPATH=${stage}/lib/python3/dist-packages"
                          /usr/bin/python3 -c "import crossdiv; V, F = crossdiv.subdivide([[0,0,0],[1,0,0],[0,1,0]], [[0,1,2]]); assert V.shape == (6, 3)"
                  COMMAND_ERROR_IS_FATAL ANY)
endif()
